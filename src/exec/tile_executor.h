// The back end: TBB workers take whole tiles, draw each tile's bins into per-thread scratch,
// and write the tile to the framebuffer once. No two workers touch the same pixels: no locks.
#pragma once
#include <cstdint>
#include <memory>

#include "fastshade/image.h"
#include "frame/frame.h"
#include "shade/method.h"

namespace fastshade {

struct AovFrame;  // exec/aov_pass.h

struct BackEndCounts {
  long long tiles_nonempty = 0;
  long long covered_pixels = 0;
  long long path_pixels[kShadePathCount] = {};  // classified frames: visible pixels per path
  long long single_path_tiles = 0;  // classified frames: tiles that ran one path's kernel alone
  void add(const BackEndCounts& o) {
    tiles_nonempty += o.tiles_nonempty;
    covered_pixels += o.covered_pixels;
    for (int p = 0; p < kShadePathCount; ++p) path_pixels[p] += o.path_pixels[p];
    single_path_tiles += o.single_path_tiles;
  }
};

class TileExecutor {
 public:
  TileExecutor();
  ~TileExecutor();
  // Runs inside the caller's task arena. `image` must already have the frame's size. A non-null
  // `tile_ns` (one slot per tile) receives each tile's time (exec/frame_profile.h). A non-null
  // `aov` also writes the AOVs it names, each tile's after its colour.
  BackEndCounts run(const Frame& frame, const TileDraw& draw, Image& image, uint64_t* tile_ns = nullptr,
                    const AovFrame* aov = nullptr);

 private:
  struct Scratch;
  std::unique_ptr<Scratch> scratch_;
};

}  // namespace fastshade
