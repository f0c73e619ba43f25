#include "exec/isa.h"

#include <mutex>
#include <string>

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

// Read once, before select_isa() first narrows what Highway reports as supported.
int64_t cpu_targets() {
  static const int64_t targets = [] {
    hwy::SetSupportedTargetsForTest(0);
    return hwy::SupportedTargets() & HWY_TARGETS;
  }();
  return targets;
}

}  // namespace

void select_isa(std::string_view name) {
  // Renderers are built on several threads at once (fastshade batch), each selecting the same
  // ISA: the choice is made under a lock and Highway's globals are written only when it
  // changes, so a thread rendering meanwhile never sees them rewritten.
  static std::mutex mutex;
  static std::string selected;  // empty until the first selection
  const std::lock_guard<std::mutex> lock(mutex);
  if (name == selected) return;
  const int64_t supported = cpu_targets();
  int64_t chosen = 0;
  if (name != "best") {
    for (const IsaName& isa : kIsas)
      if (name == isa.name) chosen = isa.target;
    if (chosen == 0)
      throw InputError("--isa", "unknown ISA '" + std::string(name) +
                                    "' (expected scalar, sse4, avx2, avx512 or best)");
    if (!(supported & chosen))
      throw InputError("--isa", "this CPU or build cannot run '" + std::string(name) + "'");
  }
  hwy::SetSupportedTargetsForTest(chosen);  // 0: no restriction, the CPU's best
  hwy::GetChosenTarget().Update(hwy::SupportedTargets());
  selected = name;
}

std::string active_isa() {
  const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
  const int64_t best = targets & -targets;  // lower bits are better targets
  for (const IsaName& isa : kIsas)
    if (best == isa.target) return isa.name;
  return hwy::TargetName(best);
}

std::vector<std::string> available_isas() {
  const int64_t supported = cpu_targets();
  std::vector<std::string> names;
  for (const IsaName& isa : kIsas)
    if (supported & isa.target) names.push_back(isa.name);
  return names;
}

}  // namespace fastshade
