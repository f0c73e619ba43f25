// One number as printf would write it, for tables and messages: format_double("%.2f", 1.5).
#pragma once
#include <cstdio>
#include <string>

namespace fastshade {

inline std::string format_double(const char* spec, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, value);
  return buf;
}

}  // namespace fastshade
