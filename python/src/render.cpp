// fastshade.Renderer: every render option by its Python name; frames rendered with the GIL
// released, so several renderers in several Python threads run at once.
#include <memory>
#include <string>
#include <utility>

#include <nanobind/ndarray.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bindings.h"
#include "fastshade/render.h"
#include "scene_binding.h"

namespace nb = nanobind;

namespace fastshade::python {

namespace {

struct PyRenderer {
  Scene scene;  // the renderer's own copy: the Python scene may change afterwards
  std::unique_ptr<Renderer> renderer;
};

using ColorArray = nb::ndarray<nb::numpy, uint8_t, nb::shape<-1, -1, 3>>;

// A frame's buffers, owned by one capsule that every array it returns holds: no copies.
struct FrameBuffers {
  Image color;
  AovImages aovs;
};

template <typename T, typename... Shape>
nb::object array_of(std::vector<T>& v, const nb::capsule& owner, Shape... shape) {
  if (v.empty()) return nb::none();
  return nb::cast(nb::ndarray<nb::numpy, T>(v.data(), {std::size_t(shape)...}, owner));
}

// One frame: colour (H, W, 3) uint8, the stats as JSON text, and the AOVs asked for (None for
// the others): depth (H, W) float32, normal (H, W, 3) float32, ids (H, W) int32.
nb::tuple render_frame(PyRenderer& r, bool depth, bool normal, bool triangle_id, bool object_id) {
  auto buffers = std::make_unique<FrameBuffers>();
  RenderStats stats;
  {
    nb::gil_scoped_release unlocked;
    r.renderer->render_frame(buffers->color, AovSet{depth, normal, triangle_id, object_id}, buffers->aovs);
    stats = r.renderer->last_stats();
    stats.frames = 1;
  }
  FrameBuffers* b = buffers.release();
  nb::capsule owner(b, [](void* p) noexcept { delete static_cast<FrameBuffers*>(p); });
  const std::size_t height = b->color.height, width = b->color.width;
  return nb::make_tuple(ColorArray(b->color.rgb.data(), {height, width, 3}, owner), stats.to_json(),
                        array_of(b->aovs.depth, owner, height, width), array_of(b->aovs.normal, owner, height, width, 3),
                        array_of(b->aovs.triangle_id, owner, height, width),
                        array_of(b->aovs.object_id, owner, height, width));
}

}  // namespace

void bind_render(nb::module_& m) {
  nb::class_<PyRenderer>(m, "_Renderer")
      .def(nb::new_([](const PyScene& scene, int threads, const std::string& method, double max_error, int tile,
                       const std::string& isa, bool srgb, const std::string& brdf, const std::string& normals,
                       const std::string& gouraud, const std::string& hidden_faces, double spec_threshold,
                       const std::string& spec_method, const std::string& classifier, double classify_min_px) {
             RenderOptions o;
             o.threads = threads, o.method = method, o.max_error = max_error, o.tile_px = tile, o.isa = isa;
             o.srgb = srgb, o.brdf = brdf, o.normals = normals, o.gouraud = gouraud, o.hidden_faces = hidden_faces;
             o.spec_threshold = spec_threshold, o.spec_method = spec_method, o.classifier = classifier;
             o.classify_min_px = classify_min_px;
             auto r = std::make_unique<PyRenderer>();
             r->scene = resolved_scene(scene);
             nb::gil_scoped_release unlocked;
             r->renderer = std::make_unique<Renderer>(r->scene, o);
             return r.release();
           }),
           nb::arg("scene"), nb::arg("threads"), nb::arg("method"), nb::arg("max_error"), nb::arg("tile"),
           nb::arg("isa"), nb::arg("srgb"), nb::arg("brdf"), nb::arg("normals"), nb::arg("gouraud"),
           nb::arg("hidden_faces"), nb::arg("spec_threshold"), nb::arg("spec_method"), nb::arg("classifier"),
           nb::arg("classify_min_px"))
      .def("render", &render_frame, nb::arg("depth"), nb::arg("normal"), nb::arg("triangle_id"), nb::arg("object_id"));
  m.def("_methods", [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const MethodDescription& d : list_methods()) out.emplace_back(d.name, d.summary);
    return out;
  });
}

}  // namespace fastshade::python
