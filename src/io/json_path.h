// Reading JSON values while knowing where they are: every check throws a one-line InputError
// "SOURCE: KEY.PATH: problem". Used by the scene parser; knows nothing about scenes.
#pragma once
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace fastshade::json_path {

using nlohmann::json;

// "image" + "width" -> "image.width"; a key that is not a plain identifier is quoted:
// "materials" + "my gold" -> materials["my gold"].
std::string child(const std::string& path, std::string_view key);
// "objects" + 2 -> "objects[2]".
std::string element(const std::string& path, size_t index);

// A number for messages: integers without a fraction, others with up to 9 significant digits.
std::string format_number(double value);
// What a value is, for "got ...": scalars as JSON text (shortened), containers by kind.
std::string describe(const json& value);

// Parses JSON text; syntax errors name the line and column, duplicate keys name their path.
json parse(const std::string& text, const std::string& source);

// A number range; bounds are inclusive unless marked open.
struct Range {
  double lo, hi;
  bool lo_open = false, hi_open = false;
  bool contains(double v) const;
  std::string to_string() const;  // "[1, 16384]", "(0, 180)", ">= 0", "> 0"
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr Range kAnyNumber{-kInf, kInf};
inline constexpr Range kNonNegative{0, kInf};
inline constexpr Range kPositive{0, kInf, true};

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}
  const std::string& source() const { return source_; }

  // Throws InputError(source + ": " + path, problem); an empty path names only the source.
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const;

  // Checks `value` is an object whose keys are all in `allowed`.
  void expect_object(const json& value, const std::string& path,
                     const std::vector<std::string_view>& allowed) const;
  const json& expect_array(const json& value, const std::string& path) const;

  // The member or nullptr.
  static const json* find(const json& object, std::string_view key);

  int64_t integer(const json& value, const std::string& path, int64_t lo, int64_t hi) const;
  // A float-representable finite number in `range`.
  double number(const json& value, const std::string& path, const Range& range) const;
  bool boolean(const json& value, const std::string& path) const;
  std::string string(const json& value, const std::string& path) const;
  // One of `names`; returns its position in the list.
  size_t choice(const json& value, const std::string& path,
                const std::vector<std::string_view>& names) const;
  // [x, y, z] with each component in `range`.
  glm::dvec3 vec3(const json& value, const std::string& path, const Range& range) const;
  // A number (used for all three channels) or [r, g, b], each in `range`.
  glm::dvec3 scalar_or_vec3(const json& value, const std::string& path, const Range& range) const;

 private:
  std::string source_;
};

}  // namespace fastshade::json_path
