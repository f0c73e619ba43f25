// This machine's floors for a frame (docs/PERFORMANCE.md, "Floors"): what a frame cannot go
// below here, measured, so that a speed target is set against them and not guessed.
//   frame_write/threads:T     storing one 1920x1080 RGB8 frame (6.2 MB, the least a frame
//                             writes) on T threads: Time is one frame's
//   decide_triangles/ISA      the front end's per-triangle decisions (area, facing, box) in
//                             lanes, 256-triangle blocks of small triangles in L1: items are
//                             triangles
// The third floor, per-pixel Phong with its data in L1, is kernels_bench's phong_span/ISA
// (px_per_ns).
#include <benchmark/benchmark.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include "core/limits.h"
#include "core/simd_target.h"
#include "front/triangle_fate.h"

namespace fastshade {
namespace {

constexpr int kFrameWidth = 1920, kFrameHeight = 1080;  // the peer frame of docs/PERFORMANCE.md

void BM_FrameWrite(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  const std::size_t row_bytes = std::size_t(kFrameWidth) * 3;
  std::vector<unsigned char> frame(row_bytes * kFrameHeight, 1);
  tbb::task_arena arena(threads);
  unsigned char value = 0;
  for (auto _ : state) {
    ++value;  // a new value each frame: no store may be skipped
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, kFrameHeight), [&](const tbb::blocked_range<int>& rows) {
        std::memset(frame.data() + rows.begin() * row_bytes, value, rows.size() * row_bytes);
      }, tbb::static_partitioner());
    });
    benchmark::DoNotOptimize(frame.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * frame.size()));
}
BENCHMARK(BM_FrameWrite)->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()->MinTime(0.5);

// Triangles of a dense mesh at 1080p (dragon_871k: boxes of a few pixels), anywhere on screen.
TriangleColumns small_triangles(std::mt19937& rng) {
  TriangleColumns in{};
  const int32_t one = limits::kSubpixelOne;
  std::uniform_int_distribution<int32_t> x(0, kFrameWidth * one), y(0, kFrameHeight * one), d(-4 * one, 4 * one);
  for (int i = 0; i < kFateBlock; ++i) {
    const int32_t cx = x(rng), cy = y(rng);
    for (int v = 0; v < 3; ++v) {
      in.x_fx[v][i] = cx + d(rng);
      in.y_fx[v][i] = cy + d(rng);
    }
  }
  return in;
}

void BM_DecideTriangles(benchmark::State& state, Isa isa) {
  SimdTarget simd;
  try {
    simd = simd_target(isa);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  std::mt19937 rng(7);
  const TriangleColumns in = small_triangles(rng);
  TriangleFates out;
  for (auto _ : state) {
    decide_triangles(simd, in, kFateBlock, kFrameWidth, kFrameHeight, /*cull_back=*/false, out);
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kFateBlock);
}

void register_all() {
  for (const auto& [isa, name] : OptionSpellings<Isa>::kValues)
    if (isa != Isa::Best)
      benchmark::RegisterBenchmark(("decide_triangles/" + std::string(name)).c_str(), BM_DecideTriangles, isa);
}

}  // namespace
}  // namespace fastshade

int main(int argc, char** argv) {
  fastshade::register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
