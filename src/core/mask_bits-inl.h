// A mask's lanes as the bits of one integer (per-target, Highway "-inl.h"): the kernels that
// leave lanes for scalar work (a pixel store, a std::pow, a gathered triangle) walk its set
// bits.
#if defined(FASTSHADE_CORE_MASK_BITS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FASTSHADE_CORE_MASK_BITS_INL_H_
#undef FASTSHADE_CORE_MASK_BITS_INL_H_
#else
#define FASTSHADE_CORE_MASK_BITS_INL_H_
#endif

#include <cstdint>
#include <cstring>

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace fastshade {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Bit i set where lane i of m is; vectors of at most 64 lanes.
template <class D>
HWY_INLINE uint64_t MaskBits(D d, hn::Mask<D> m) {
  uint8_t bytes[8] = {};
  hn::StoreMaskBits(d, m, bytes);
  uint64_t bits = 0;
  std::memcpy(&bits, bytes, sizeof(bits));
  return bits;
}

}  // namespace HWY_NAMESPACE
}  // namespace fastshade
HWY_AFTER_NAMESPACE();

#endif  // include guard toggle
