#include "core/simd_target.h"

#include <hwy/highway.h>
#include <hwy/targets.h>

#include "fastshade/error.h"

namespace fastshade {

namespace {

struct IsaTarget {
  Isa isa;
  int64_t target;
};
// Isa::Scalar is Highway's portable fallback: HWY_SCALAR on x86-64 builds whose baseline is
// SSE2 (this one), HWY_EMU128 elsewhere; whichever the build compiled.
constexpr int64_t kScalarTarget = (HWY_TARGETS & HWY_SCALAR) ? HWY_SCALAR : HWY_EMU128;
constexpr IsaTarget kIsas[] = {
    {Isa::Scalar, kScalarTarget}, {Isa::Sse4, HWY_SSE4}, {Isa::Avx2, HWY_AVX2}, {Isa::Avx512, HWY_AVX3}};

int64_t cpu_targets() { return hwy::SupportedTargets() & HWY_TARGETS; }

// The table index Highway itself would use had the CPU supported `target` alone: its
// ChosenTarget::Update then GetIndex, with the fallback's bit always set.
uint32_t table_index(int64_t target) {
  const int64_t mask =
      (HWY_CHOSEN_TARGET_SHIFT(target) | HWY_CHOSEN_TARGET_MASK_SCALAR) & HWY_CHOSEN_TARGET_MASK_TARGETS;
  return static_cast<uint32_t>(hwy::Num0BitsBelowLS1Bit_Nonzero64(static_cast<uint64_t>(mask)));
}

int64_t best_target() {
  const int64_t targets = cpu_targets();
  return targets & -targets;  // lower bits are better targets
}

}  // namespace

SimdTarget simd_target(Isa isa) {
  if (isa == Isa::Best) return {table_index(best_target())};
  for (const IsaTarget& t : kIsas)
    if (t.isa == isa) {
      if (!(cpu_targets() & t.target))
        throw InputError("--isa", "this CPU or build cannot run '" + std::string(option_name(isa)) + "'");
      return {table_index(t.target)};
    }
  throw InputError("--isa", "not an ISA (value " + std::to_string(static_cast<int>(isa)) + ")");
}

Isa simd_target_isa(SimdTarget target) {
  if (target.table_index == 0) target = simd_target(Isa::Best);
  for (const IsaTarget& t : kIsas)
    if (table_index(t.target) == target.table_index) return t.isa;
  return Isa::Best;
}

std::string simd_target_name(SimdTarget target) {
  if (const Isa isa = simd_target_isa(target); isa != Isa::Best) return std::string(option_name(isa));
  const int64_t best = best_target();  // a target outside kIsas (the build's HWY_TARGETS)
  return table_index(best) == target.table_index ? hwy::TargetName(best) : "unknown";
}

Isa resolve_isa(Isa isa) {
  const std::vector<Isa> isas = available_isas();
  if (isa == Isa::Best) return isas.back();
  (void)simd_target(isa);  // refuses an ISA this CPU cannot run
  return isa;
}

std::vector<Isa> available_isas() {
  std::vector<Isa> out;
  for (const IsaTarget& t : kIsas)
    if (cpu_targets() & t.target) out.push_back(t.isa);
  return out;
}

}  // namespace fastshade
