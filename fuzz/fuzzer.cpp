// One libFuzzer target, chosen at compile time (FASTSHADE_FUZZ_TARGET, one of
// fastshade::fuzz::kTargets): a finding is reported on stderr and aborts, so libFuzzer keeps
// the input. Built and run by tools/fuzz.sh; docs/FUZZING.md.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (auto finding = fastshade::fuzz::run_target(FASTSHADE_FUZZ_TARGET, data, size)) {
    std::fprintf(stderr, "fastshade finding (%s): %s\n", FASTSHADE_FUZZ_TARGET, finding->c_str());
    std::abort();
  }
  return 0;
}
