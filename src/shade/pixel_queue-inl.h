// The pixel queue's kernels (shade/pixel_queue.h) per target (Highway's "-inl.h" convention):
// lanes that passed the depth test join the queue with their interpolated normal, and the
// queue is lit a full vector at a time with Phong's own colour (PhongColorFromNormal), so a
// pixel gets the same bits as if its triangle had lit it at once.
#if defined(FASTSHADE_SHADE_PIXEL_QUEUE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_SHADE_PIXEL_QUEUE_INL_H_
#undef FASTSHADE_SHADE_PIXEL_QUEUE_INL_H_
#else
#define FASTSHADE_SHADE_PIXEL_QUEUE_INL_H_
#endif

#include <algorithm>
#include <bit>

#include <hwy/highway.h>

#include "core/mask_bits-inl.h"
#include "shade/phong_color-inl.h"
#include "shade/pixel_queue.h"

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {

static_assert(3 * kMaxLanes <= limits::kPixelQueueCapacity, "a queue below one vector, a vector added, a vector read");

// LightQueueFn for a viewer at infinity: the entries' colours, stored in the order they came.
template <LobeKernel kLobe>
void LightQueue(PixelQueue& q, const TileTarget& tt, bool all) {
  using D = hn::ScalableTag<float>;
  const D d;
  const hn::RebindToUnsigned<D> du;
  const int lanes = static_cast<int>(hn::Lanes(d));
  const int n = all ? q.count : q.count - q.count % lanes;
  PhongSpanInput in;
  in.material = q.material;
  in.shade = q.shade;
  const LaneOffsets<D> unused{};  // only a local viewer reads the pixel's offsets
  alignas(64) uint32_t rgba[kMaxLanes];
  for (int j = 0; j < n; j += lanes) {
    auto nx = hn::Load(d, q.nx + j), ny = hn::Load(d, q.ny + j), nz = hn::Load(d, q.nz + j);
    Normalize(d, nx, ny, nz);
    const ColorVecs<D> c = PhongColorFromNormal<false, kLobe>(d, in, nx, ny, nz, unused);
    hn::Store(hn::Xor(PackRGBA(d, c.r, c.g, c.b, q.shade->srgb), hn::Set(du, q.alpha_xor)), du, rgba);
    const int m = std::min(lanes, n - j);
    for (int i = 0; i < m; ++i) tt.color[q.at[j + i]] = rgba[i];
  }
  // The rest, fewer than one vector, moves to the front a whole vector at a time (n is a
  // multiple of the width, so the loads are aligned).
  if (n > 0 && n < q.count) {
    const hn::RebindToSigned<D> di;
    hn::Store(hn::Load(d, q.nx + n), d, q.nx);
    hn::Store(hn::Load(d, q.ny + n), d, q.ny);
    hn::Store(hn::Load(d, q.nz + n), d, q.nz);
    hn::Store(hn::Load(di, q.at + n), di, q.at);
  }
  q.count -= n;
}

// The lanes of `pass`: depth stored now, normal and tile index appended to the queue; the
// queue is lit once it holds a whole vector. AVX-512 compresses lanes natively, in a register
// and then stored as a whole vector past the count (the capacity allows it): the form that
// compresses straight to memory (CompressStore) is microcoded on Zen 4, 21.5 ns against
// 1.4 ns a vector (f7e0bfb). On narrower targets Highway emulates the
// compress with tables, which cost more than copying the passed lanes one by one (callgrind,
// AVX2, bunny phong: 331 M instructions against 258 M; 7839c40).
template <LobeKernel kLobe, class D, class V = hn::Vec<D>>
HWY_INLINE void EnqueuePassed(D d, hn::Mask<D> pass, V z, V nx, V ny, V nz, const int32_t* lane_at,
                              const PhongSpanInput& in, const TileTarget& tt) {
  PixelQueue& q = *tt.pending;
  if (q.material != in.material || q.shade != in.shade || q.light != &LightQueue<kLobe> ||
      q.alpha_xor != tt.alpha_xor) {
    if (q.count > 0) LightQueue<kLobe>(q, tt, true);
    q.material = in.material;
    q.shade = in.shade;
    q.light = &LightQueue<kLobe>;
    q.alpha_xor = tt.alpha_xor;
  }
  alignas(64) float lane_z[kMaxLanes];
  hn::Store(z, d, lane_z);
#if HWY_TARGET <= HWY_AVX3
  for (uint64_t passed = MaskBits(d, pass); passed; passed &= passed - 1) {
    const int lane = std::countr_zero(passed);
    tt.depth[lane_at[lane]] = lane_z[lane];
  }
  const hn::RebindToSigned<D> di;
  hn::StoreU(hn::Compress(nx, pass), d, q.nx + q.count);
  hn::StoreU(hn::Compress(ny, pass), d, q.ny + q.count);
  hn::StoreU(hn::Compress(nz, pass), d, q.nz + q.count);
  hn::StoreU(hn::Compress(hn::LoadU(di, lane_at), hn::RebindMask(di, pass)), di, q.at + q.count);
  q.count += static_cast<int>(hn::CountTrue(d, pass));
#else
  alignas(64) float lane_nx[kMaxLanes], lane_ny[kMaxLanes], lane_nz[kMaxLanes];
  hn::Store(nx, d, lane_nx);
  hn::Store(ny, d, lane_ny);
  hn::Store(nz, d, lane_nz);
  int n = q.count;
  for (uint64_t passed = MaskBits(d, pass); passed; passed &= passed - 1, ++n) {
    const int lane = std::countr_zero(passed);
    tt.depth[lane_at[lane]] = lane_z[lane];
    q.nx[n] = lane_nx[lane];
    q.ny[n] = lane_ny[lane];
    q.nz[n] = lane_nz[lane];
    q.at[n] = lane_at[lane];
  }
  q.count = n;
#endif
  if (q.count >= static_cast<int>(hn::Lanes(hn::ScalableTag<float>()))) LightQueue<kLobe>(q, tt, false);
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
