// Small text helpers shared by the mesh pre-checks: whitespace tokens, numbers parsed the way the
// checks need them, and quoting of file content for one-line error messages.
#pragma once
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <string>
#include <string_view>

namespace fastshade::io {

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Splits `line` into whitespace-separated tokens, calling f(token) for each; stops early when f
// returns false.
template <class F>
void for_each_token(std::string_view line, F&& f) {
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start && !f(line.substr(start, i - start))) return;
  }
}

enum class NumberStatus { Ok, NotANumber, NotFinite };

// The whole token must be a decimal number (an optional leading '+' is accepted, as C++ streams
// do). "nan", "inf" and values beyond double range parse but report NotFinite.
inline NumberStatus parse_number(std::string_view tok, double& out) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  if (tok.empty() || tok.front() == '+') return NumberStatus::NotANumber;
  const char* end = tok.data() + tok.size();
  const auto [ptr, ec] = std::from_chars(tok.data(), end, out);
  if (ptr != end) return NumberStatus::NotANumber;
  if (ec == std::errc::result_out_of_range) {
    // from_chars reports overflow and underflow alike and leaves `out` alone; strtod tells
    // them apart (the token is known to be a valid number).
    out = std::strtod(std::string(tok).c_str(), nullptr);
    return std::isfinite(out) ? NumberStatus::Ok : NumberStatus::NotFinite;
  }
  if (ec != std::errc()) return NumberStatus::NotANumber;
  return std::isfinite(out) ? NumberStatus::Ok : NumberStatus::NotFinite;
}

// A whole-token integer with an optional leading '+'.
inline bool parse_integer(std::string_view tok, int64_t& out) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  if (tok.empty() || tok.front() == '+') return false;
  const char* end = tok.data() + tok.size();
  const auto [ptr, ec] = std::from_chars(tok.data(), end, out);
  return ec == std::errc() && ptr == end;
}

// File content for a message: in single quotes, at most 32 bytes, control and non-ASCII bytes
// as \xNN, so the message stays one printable line.
inline std::string quote(std::string_view s) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out = "'";
  const std::size_t n = s.size() < 32 ? s.size() : 32;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (s.size() > n) out += "...";
  out += "'";
  return out;
}

}  // namespace fastshade::io
