#include "core/simd_target.h"

#include <hwy/highway.h>
#include <hwy/targets.h>

#include "fastshade/error.h"

namespace fastshade {

namespace {

struct IsaName {
  const char* name;
  int64_t target;
};
// "scalar" is Highway's portable fallback: HWY_SCALAR on x86-64 builds whose baseline is
// SSE2 (this one), HWY_EMU128 elsewhere; whichever the build compiled.
constexpr int64_t kScalarTarget = (HWY_TARGETS & HWY_SCALAR) ? HWY_SCALAR : HWY_EMU128;
constexpr IsaName kIsas[] = {{"scalar", kScalarTarget}, {"sse4", HWY_SSE4}, {"avx2", HWY_AVX2},
                             {"avx512", HWY_AVX3}};

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

SimdTarget simd_target(std::string_view name) {
  if (name == "best") return {table_index(best_target())};
  for (const IsaName& isa : kIsas)
    if (name == isa.name) {
      if (!(cpu_targets() & isa.target))
        throw InputError("--isa", "this CPU or build cannot run '" + std::string(name) + "'");
      return {table_index(isa.target)};
    }
  throw InputError("--isa", "unknown ISA '" + std::string(name) + "' (expected scalar, sse4, avx2, avx512 or best)");
}

std::string simd_target_name(SimdTarget target) {
  if (target.table_index == 0) target = simd_target("best");
  for (const IsaName& isa : kIsas)
    if (table_index(isa.target) == target.table_index) return isa.name;
  const int64_t best = best_target();  // a target outside kIsas (the build's HWY_TARGETS)
  return table_index(best) == target.table_index ? hwy::TargetName(best) : "unknown";
}

std::vector<std::string> available_isas() {
  std::vector<std::string> names;
  for (const IsaName& isa : kIsas)
    if (cpu_targets() & isa.target) names.push_back(isa.name);
  return names;
}

}  // namespace fastshade
