// The limits and magic numbers the whole pipeline shares, with the reasoning that bounds each.
// A folder's own tuning constants are in its *_limits.h (exec/, classify/, front/, shade/), in
// the same namespace, so every one reads limits::kName.
#pragma once
#include <cstddef>
#include <cstdint>

#include "fastshade/scene.h"

namespace fastshade::limits {

// Sub-pixel precision: 8 fractional bits, as Direct3D 10+ and llvmpipe (FIXED_ORDER 8). Finer
// would shrink the guard band below; 8 bits put vertices within 1/512 px of their true place.
inline constexpr int kSubpixelBits = 8;
inline constexpr int32_t kSubpixelOne = 1 << kSubpixelBits;

// Guard band: screen coordinates stay inside [-kGuardPx, kGuardPx) after clipping, so a
// fixed-point coordinate needs 15 + 8 = 23 bits plus sign, edge deltas 24 bits, and an edge
// function (a product of two deltas) 48 bits: exact in int64, and exact in a double's 53-bit
// mantissa, which the span solver relies on. kMaxImageSide (16384) fits inside the band.
inline constexpr int32_t kGuardPx = 1 << 15;
static_assert(kMaxImageSide <= kGuardPx / 2, "the image must sit well inside the guard band");

// Tiles: powers of two. 8 px is the smallest block the shading kernels seed from, so tile
// edges never cut a block; 256 px keeps one tile's colour + depth scratch (256 KiB + 256 KiB)
// inside a core's L2.
inline constexpr int kMinTilePx = 8;
inline constexpr int kMaxTilePx = 256;
// --tile 0 (exec/tile_size.h) sizes the tile per frame: the largest of kSizedTileMaxPx,
// kSizedTileMaxPx / 2, ... that still gives every worker kTilesPerWorker tiles, and never
// below kSizedTileMinPx. Large tiles pay each triangle's per-tile work (placement, planes,
// the hybrid step, auto's path dispatch) fewer times: on 2 threads 128 px against 64 px took
// spot 4K auto 2.67 vs 3.38 ms and gouraud 2.09 vs 2.30, bunny auto 4.18 vs 4.40, dragon
// 21.5 vs 22.2 (28a9ce8); 256 px gained nothing more. Many workers
// need small tiles instead: the load-balance model of docs/SCALING.md puts the 1080p dragon
// at 7.8x on 8 workers with 64 px (510 tiles) against 7.2x with 128 px (135 tiles), and at
// 56x on 64 workers with 16 px against 42x with 64 px: the largest tile is the critical
// path. 32 tiles a worker picks 64 px at 8 workers and 16 px at 64 workers for 1080p, and
// 128 px on 1 or 2 workers for 1080p and 4K. The default (RenderOptions) stays a fixed 64 px,
// as the pipeline issue (#2) sets it and llvmpipe fixes it (TILE_ORDER 6).
inline constexpr int kSizedTileMaxPx = 128;
inline constexpr int kSizedTileMinPx = 16;
inline constexpr int kTilesPerWorker = 32;

// Cache line of every x86-64 CPU the ISAs target. The framebuffer starts on one (io/
// image_bytes.cpp) and tile rows are streamed in whole ones (exec/tile_io.cpp): a line written
// partly by streaming and partly by ordinary stores costs a trip to memory.
inline constexpr int kCacheLineBytes = 64;

// Attributes are seeded from their plane equation at every aligned block of this many pixels in x
// and stepped by constant increments inside it (the paper's eq. 1-2, lanes i = seed + i dI): a
// pixel's value depends only on its position, never on the tile, the span or the vector width that
// drew it, and no drift builds up (forward differencing in float drifts 0.4 LSB over 65536 px:
// docs/PAPER.md, "Plane evaluation precision"). 16 = the widest float vector (AVX-512).
inline constexpr int kSeedBlockPx = 16;
static_assert((kSeedBlockPx & (kSeedBlockPx - 1)) == 0, "blocks are found by masking");

// --gouraud sierpinski splits triangles whose bounding box reaches this many pixels on a side:
// half the default tile, so a split triangle's parts usually land in different bins.
inline constexpr int kSierpinskiMinPx = 32;

// Front-end chunk: triangles per binning chunk. Enough to amortise a chunk's bin headers
// (one counter per tile), small enough that 2 threads get many chunks on a 70k mesh.
inline constexpr int kTrianglesPerChunk = 4096;

// Self-occlusion (front/self_occlusion.h). Each of a mesh's rims (boundary loops) costs every
// back face a box test at setup; a closed mesh has none, the bunny a few (holes underneath).
// A box test is a few instructions against the hundreds a drawn triangle costs, so 256 rims
// still cost less than culling saves; a mesh with more (a triangle soup, an unwelded
// tessellation) is drawn whole.
inline constexpr std::size_t kMaxOcclusionRims = 256;
// A connected part whose capped volume (6 V, as a sum of determinants) is below this share of
// its box's largest side cubed is a flat sheet, with no inside to hide faces in. Rounding of
// the sum is about 1e-16 relative per term, so 1e-9 is far above it for any mesh below 10^6
// triangles, and far below that of any real solid (a rod 1000 times longer than thick: 6e-6).
inline constexpr double kFlatVolumeRelative = 1e-9;

// `auto`: what of --max-error the float kernels keep for their own rounding. The Gouraud
// path's colour planes (c/w, 1/w in float, one division) err by a few 1e-7 relative, 1e-4 of
// an 8-bit step; 0.01 LSB leaves two orders of magnitude, so that a triangle whose bound
// error is below max_error - 0.01 LSB stays below max_error as drawn. Rounding both images
// to 8 bits then differs by at most ceil(max_error) steps.
inline constexpr double kAutoFloatReserveLsb = 0.01;

// Largest error of N.H as the float kernels compute it, for unit N and H at c = N.H near 1, in
// units of u = 2^-24 (docs/STABILITY.md, "B1"): |N| after the 1/sqrt (sqrt and a division) is
// 1 within 4.5u, |H| (glm::normalize) within 3.5u, and the three-term dot product rounds within
// 3u: 11u, kept at the 12u of the Newton 1/sqrt used before 636009e (5.5u), so that the
// double fallback's threshold did not move.
// Through c^n it becomes a relative error of n times that: 0.3 % at n = 1e4, 72 % at 1e6.
inline constexpr double kFloatNdotHError = 12.0 * 0x1p-24;
// The share of phong's 1-LSB bound that this rounding may take (the rest covers the normal's
// direction and the lobe's own rounding, far smaller): a material whose lights can move
// ks n kFloatNdotHError past half a step is shaded in double instead (docs/STABILITY.md,
// "Fallbacks"). With one white light and ks = 0.5 that is n > 5,480.
inline constexpr double kFloatSpecularBudgetLsb = 0.5;

// Bin plan: tiles per parallel block. Each block reads kBinPlanTiles consecutive counters
// (1 KiB) of every chunk in turn, so its walk over chunks stays sequential in memory; a 1080p
// frame with 16 px tiles (8160 tiles) still makes 32 blocks for the workers.
inline constexpr int kBinPlanTiles = 256;

// Vertex stage: vertices per parallel block (TBB's grain). A vertex costs ~5-15 ns (transform
// in lanes, plus lighting for gouraud; dragon_871k, measured), so a block is 20-60 us: far
// above the cost of handing it out, and a 35k-vertex mesh still makes 9 blocks.
inline constexpr int kVerticesPerBlock = 4096;
// Vertices lit together in SIMD lanes (light/vertex_light.h): their normals and positions wait
// in two local arrays of this many (6 KB, in L1), and the call and its tail cost are spread
// over 16 vectors at 16 lanes.
inline constexpr int kVertexLightBatch = 256;

// `phong` on small triangles: pixels that passed the depth test wait with their normal in the
// tile's queue (shade/pixel_queue.h) and are lit a full vector at a time. The queue is lit as
// soon as it holds one vector (at most 16 floats) and a triangle's vector adds at most 16
// more, so it never holds 32; lighting its last partial vector reads up to 16 past that: 64
// entries (1 KiB of normals and indices) leave room. Measured: docs/PERFORMANCE.md, "Kept, and
// what it bought".
inline constexpr int kPixelQueueCapacity = 64;

// Largest specular exponent accepted: the kernels' approximations are specified up to 1e6.
inline constexpr double kMaxShininess = 1e6;

}  // namespace fastshade::limits
