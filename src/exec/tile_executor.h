// The back end: TBB workers take whole tiles, draw each tile's bins into per-thread scratch,
// and write the tile to the framebuffer once. No two workers touch the same pixels: no locks.
#pragma once
#include <cstdint>
#include <memory>

#include "fastshade/image.h"
#include "frame/frame.h"
#include "shade/method.h"

namespace fastshade {

struct BackEndCounts {
  long long tiles_nonempty = 0;
  long long covered_pixels = 0;
};

class TileExecutor {
 public:
  TileExecutor();
  ~TileExecutor();
  // Runs inside the caller's task arena. `image` must already have the frame's size. A non-null
  // `tile_ns` (one slot per tile) receives each tile's time (exec/frame_profile.h).
  BackEndCounts run(const Frame& frame, DrawTriangleFn draw, Image& image,
                    uint64_t* tile_ns = nullptr);

 private:
  struct Scratch;
  std::unique_ptr<Scratch> scratch_;
};

}  // namespace fastshade
