// The ISA is a renderer's own (core/simd_target.h): renderers built with different --isa in one
// process each run theirs, side by side, as the Python module's users will build them.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "core/simd_target.h"
#include "fastshade/error.h"
#include "fastshade/render.h"
#include "fastshade/scene.h"
#include "front/shade_setup.h"
#include "shade/method.h"

namespace fastshade {
namespace {

Scene default_scene() { return parse_scene(default_scene_json(), "default scene", "."); }

TEST(PerRendererIsa, EachIsaSelectsItsOwnKernels) {
  const std::vector<Isa> isas = available_isas();
  if (isas.size() < 2) GTEST_SKIP() << "this CPU runs one ISA only: nothing to tell apart";
  const Scene scene = default_scene();
  const ShadeConstants k = shade_constants(scene, view_transform(scene));
  ASSERT_FALSE(k.lights.empty());
  for (const ShadingMethod id : {ShadingMethod::Phong, ShadingMethod::Hybrid, ShadingMethod::Gouraud, ShadingMethod::Auto}) {
    const Method& method = find_method(id);
    const std::string_view name = option_name(id);
    std::vector<DrawTriangleFn> kernels;
    for (const Isa isa : isas) {
      const TileDraw draw = method.select(simd_target(isa), k, RenderOptions{});
      // `auto` draws through a per-triangle dispatcher; its paths are the kernels.
      kernels.push_back(method.classifies ? draw.path[static_cast<int>(ShadePath::Specular)] : draw.any);
      ASSERT_NE(kernels.back(), nullptr) << name << " " << option_name(isa);
    }
    for (std::size_t a = 0; a < kernels.size(); ++a)
      for (std::size_t b = a + 1; b < kernels.size(); ++b)
        EXPECT_NE(kernels[a], kernels[b]) << name << ": " << option_name(isas[a]) << " and " << option_name(isas[b]) << " share a kernel";
  }
}

TEST(PerRendererIsa, TwoRenderersWithDifferentIsasRunSideBySide) {
  const std::vector<Isa> isas = available_isas();
  if (isas.size() < 2) GTEST_SKIP() << "this CPU runs one ISA only: nothing to tell apart";
  const Scene scene = default_scene();
  RenderOptions first, last;
  first.isa = isas.front();  // scalar
  last.isa = isas.back();    // the best
  const Image solo_first = render(scene, first), solo_last = render(scene, last);
  Renderer a(scene, first), b(scene, last);  // b built after a: a must keep its own ISA
  Image image_a, image_b;
  // Both at once on two threads, then one after the other.
  std::thread ta([&] { a.render_frame(image_a); }), tb([&] { b.render_frame(image_b); });
  ta.join();
  tb.join();
  EXPECT_EQ(a.last_stats().isa, option_name(first.isa));
  EXPECT_EQ(b.last_stats().isa, option_name(last.isa));
  EXPECT_EQ(image_a.rgb, solo_first.rgb);
  EXPECT_EQ(image_b.rgb, solo_last.rgb);
  b.render_frame(image_b);
  a.render_frame(image_a);
  EXPECT_EQ(a.last_stats().isa, option_name(first.isa));
  EXPECT_EQ(image_a.rgb, solo_first.rgb);
}

TEST(PerRendererIsa, UnknownOrUnrunnableIsaIsAnInputError) {
  RenderOptions o;
  o.isa = static_cast<Isa>(99);  // outside the enum
  EXPECT_THROW(validate(o), InputError);
  EXPECT_THROW(parse_option<Isa>("neon", "--isa"), InputError);
  const std::vector<Isa> runnable = available_isas();
  for (const auto& [isa, name] : OptionSpellings<Isa>::kValues) {
    o.isa = isa;
    if (isa == Isa::Best || std::find(runnable.begin(), runnable.end(), isa) != runnable.end())
      EXPECT_NO_THROW(validate(o)) << name;
    else
      EXPECT_THROW(validate(o), InputError) << name << " is not in available_isas()";
  }
}

}  // namespace
}  // namespace fastshade
