// The median every timing in fastshade reports (medians resist the one-off stalls of a shared
// machine; docs/PERFORMANCE.md, "The machines, and why only ratios count"). 0 for no values.
#pragma once
#include <algorithm>
#include <vector>

namespace fastshade {

inline double median(std::vector<double> values) {
  const std::size_t n = values.size();
  if (n == 0) return 0.0;
  std::sort(values.begin(), values.end());
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace fastshade
