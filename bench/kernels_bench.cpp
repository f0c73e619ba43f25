// Span-kernel micro-benchmarks: pixels per nanosecond for 64-pixel spans with data in L1, on
// every ISA this CPU runs. Run (Release build):
//   build/kernels_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include "core/simd_target.h"
#include "frame/edge_function.h"
#include "light/brdf.h"
#include "shade/span_kernels_testing.h"

namespace {

using namespace fastshade;

constexpr int kSpan = 64, kY = 40, kX0 = 40;

struct Setup {
  SetupTriangle tri{};
  Barycentrics bary;
  ShadeConstants shade;
  MaterialConstants material;
  GouraudSpanInput gouraud;
  PhongSpanInput phong;
  std::vector<float> depth = std::vector<float>(512);
  std::vector<uint32_t> color = std::vector<uint32_t>(512);

  explicit Setup(const std::string& brdf) {
    // A triangle 300 px wide around the span, depth in front of the cleared buffer.
    const int32_t xs[3] = {0, 300 * 256, 0}, ys[3] = {0, 0, 300 * 256};
    for (int i = 0; i < 3; ++i) {
      tri.x_fx[i] = xs[i];
      tri.y_fx[i] = ys[i];
      tri.depth[i] = 0.5f;
      tri.inv_w[i] = 1.0f / (2.0f + i);
    }
    bary = barycentrics(tri, triangle_edges(tri));
    shade.ambient = glm::vec3(0.1f);
    shade.lights.push_back({glm::normalize(glm::vec3(1, 1, 1)), glm::normalize(glm::vec3(1, 1, 2.732f)), glm::vec3(1)});
    material = {glm::vec3(0.7f), glm::vec3(0.5f), 100.0f, 100.0, make_brdf(parse_option<BrdfChoice>(brdf, "bench"), 100.0)};
    const Plane depth_plane = make_plane(bary, 0.5, 0.5, 0.5);
    const glm::vec3 colors[3] = {{0.2f, 0.3f, 0.9f}, {0.5f, 0.4f, 0.1f}, {0.8f, 0.1f, 0.5f}};
    gouraud.bary = bary;
    gouraud.depth = depth_plane;
    set_gouraud_colors(gouraud, bary, colors, tri.inv_w);
    phong.bary = bary;
    phong.depth = depth_plane;
    const glm::vec3 n[3] = {glm::normalize(glm::vec3(0.3f, 0.1f, 1)), glm::normalize(glm::vec3(-0.2f, 0.2f, 1)),
                            glm::normalize(glm::vec3(0.1f, -0.3f, 1))};
    for (int c = 0; c < 3; ++c)
      phong.n[c] = make_plane(bary, n[0][c] * tri.inv_w[0], n[1][c] * tri.inv_w[1], n[2][c] * tri.inv_w[2]);
    phong.material = &material;
    phong.shade = &shade;
  }
  // Only the span's own depths are reset between calls (4 vector stores at 16 lanes), so every
  // pixel passes the depth test and is shaded; resetting the whole 512-float row cost more
  // than the kernel itself.
  RowTarget row() {
    std::fill(depth.begin() + kX0, depth.begin() + kX0 + kSpan, 1.0f);
    return {depth.data(), color.data()};
  }
};

template <typename Kernel>
void run(benchmark::State& state, const std::string& isa, Kernel kernel, const std::string& brdf = "exact") {
  SimdTarget simd;
  try {
    simd = simd_target(parse_option<Isa>(isa, "isa"));
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  Setup s(brdf);
  for (auto _ : state) {
    kernel(simd, s, s.row());
    benchmark::ClobberMemory();
  }
  state.counters["px_per_ns"] = benchmark::Counter(double(kSpan) * state.iterations(),
                                                    benchmark::Counter::kIsRate);
  state.counters["px_per_ns"].value /= 1e9;
}

void register_all() {
  for (const char* isa_name : {"scalar", "sse4", "avx2", "avx512"}) {
    const std::string isa = isa_name;
    benchmark::RegisterBenchmark(("gouraud_span/" + isa).c_str(), [isa](benchmark::State& st) {
      run(st, isa, [](SimdTarget simd, Setup& s, RowTarget r) {
        gouraud_span(simd, s.gouraud, false, kY, kX0, kX0 + kSpan - 1, r);
      });
    });
    benchmark::RegisterBenchmark(("phong_span/" + isa).c_str(), [isa](benchmark::State& st) {
      run(st, isa, [](SimdTarget simd, Setup& s, RowTarget r) {
        phong_span(simd, s.phong, kY, kX0, kX0 + kSpan - 1, r);
      });
    });
    for (int step : {4, 16})
      benchmark::RegisterBenchmark(("hybrid_span_step" + std::to_string(step) + "/" + isa).c_str(),
                                   [isa, step](benchmark::State& st) {
                                     run(st, isa, [step](SimdTarget simd, Setup& s, RowTarget r) {
                                       hybrid_span(simd, s.phong, {step, kX0, kX0 + kSpan - 1}, kY, kX0,
                                                   kX0 + kSpan - 1, r);
                                     });
                                   });
    for (const char* brdf : {"schlick", "schlick-pow2", "poly3"})
      benchmark::RegisterBenchmark(("phong_span_" + std::string(brdf) + "/" + isa).c_str(), [isa, brdf](benchmark::State& st) {
        run(
            st, isa,
            [](SimdTarget simd, Setup& s, RowTarget r) { phong_span(simd, s.phong, kY, kX0, kX0 + kSpan - 1, r); },
            brdf);
      });
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
