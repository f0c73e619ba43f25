// The SIMD target, chosen once per process: every kernel pointer is taken after this.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace fastshade {

// "scalar" (Highway's EMU128), "sse4", "avx2", "avx512" or "best". Throws InputError
// ("--isa: ...") for an unknown name or one this CPU cannot run. Thread-safe; selecting the ISA
// already selected changes nothing (so renderers may be built while others render).
void select_isa(std::string_view name);

std::string active_isa();                  // the name of the target kernels now run on
std::vector<std::string> available_isas(); // compiled and supported by this CPU, best last
}  // namespace fastshade
