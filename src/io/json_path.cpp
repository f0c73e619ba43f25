#include "io/json_path.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <set>
#include <vector>

#include "fastshade/error.h"

namespace fastshade::json_path {

namespace {

bool is_identifier(std::string_view key) {
  if (key.empty() || !(std::isalpha(static_cast<unsigned char>(key[0])) || key[0] == '_'))
    return false;
  for (char c : key) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  }
  return true;
}

// JSON text on one line, ASCII only (dump escapes control characters and, asked to, non-ASCII).
std::string one_line(const json& value) {
  return value.dump(-1, ' ', true, json::error_handler_t::replace);
}

// Messages stay one line whatever the library put in them.
std::string flatten(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

// "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..." ->
// "line 3, column 5: syntax error ...".
std::string strip_json_prefix(std::string what) {
  if (what.rfind("[json.exception.", 0) == 0) {
    size_t close = what.find("] ");
    if (close != std::string::npos) what.erase(0, close + 2);
  }
  static const std::string kAt = "parse error at ";
  if (what.rfind(kAt, 0) == 0) what.erase(0, kAt.size());
  return flatten(what);
}

// Tracks the path of the container being parsed, to name duplicate keys.
struct DuplicateKeyCheck {
  struct Frame {
    bool array = false;
    size_t next_index = 0;
    std::string path, last_key;
    std::set<std::string> keys;
  };
  const std::string& source;
  std::vector<Frame> stack;

  std::string next_child_path() {
    if (stack.empty()) return "";
    Frame& top = stack.back();
    return top.array ? element(top.path, top.next_index++) : child(top.path, top.last_key);
  }

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start: {
        Frame frame;
        frame.array = event == json::parse_event_t::array_start;
        frame.path = next_child_path();
        stack.push_back(std::move(frame));
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack.pop_back();
        break;
      case json::parse_event_t::key: {
        Frame& top = stack.back();
        top.last_key = parsed.get<std::string>();
        if (!top.keys.insert(top.last_key).second) {
          const std::string path = child(top.path, top.last_key);
          throw InputError(source + ": " + path, "duplicate key");
        }
        break;
      }
      case json::parse_event_t::value:
        if (!stack.empty() && stack.back().array) ++stack.back().next_index;
        break;
    }
    return true;
  }
};

// "a number in [1, 2]" or "a number >= 0".
std::string a_number(const Range& range) {
  return std::string(std::isinf(range.hi) ? "a number " : "a number in ") + range.to_string();
}

}  // namespace

std::string child(const std::string& path, std::string_view key) {
  // (Strings are built by appending: GCC 12 warns falsely on "literal" + std::string.)
  std::string quoted = is_identifier(key) ? std::string(key)
                                          : std::string("[").append(one_line(json(key))).append("]");
  if (path.empty()) return quoted;
  return quoted[0] == '[' ? path + quoted : path + "." + quoted;
}

std::string element(const std::string& path, size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

std::string format_number(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15)
    return std::to_string(static_cast<long long>(value));
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
}

std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      if (value.empty()) return "an empty array";
      return "an array of " + std::to_string(value.size()) +
             (value.size() == 1 ? " element" : " elements");
    case json::value_t::number_float:
      return format_number(value.get<double>());
    default: {
      std::string text = one_line(value);
      if (text.size() > 40) text = text.substr(0, 37) + "...";
      return text;
    }
  }
}

json parse(const std::string& text, const std::string& source) {
  DuplicateKeyCheck check{source, {}};
  try {
    return json::parse(text, std::ref(check));
  } catch (const json::parse_error& e) {
    throw InputError(source, strip_json_prefix(e.what()));
  } catch (const json::exception& e) {  // e.g. a number too large for a double
    throw InputError(source, "invalid JSON: " + strip_json_prefix(e.what()));
  }
}

bool Range::contains(double v) const {
  return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::to_string() const {
  if (std::isinf(hi)) return std::string(lo_open ? "> " : ">= ").append(format_number(lo));
  return std::string(lo_open ? "(" : "[")
      .append(format_number(lo))
      .append(", ")
      .append(format_number(hi))
      .append(hi_open ? ")" : "]");
}

void Reader::fail(const std::string& path, const std::string& problem) const {
  throw InputError(path.empty() ? source_ : source_ + ": " + path, flatten(problem));
}

void Reader::expect_object(const json& value, const std::string& path,
                           const std::vector<std::string_view>& allowed) const {
  if (!value.is_object()) fail(path, "expected an object, got " + describe(value));
  for (const auto& [key, member] : value.items()) {
    bool known = false;
    for (std::string_view name : allowed) known = known || key == name;
    if (known) continue;
    std::string names;
    for (std::string_view name : allowed) names += (names.empty() ? "" : ", ") + std::string(name);
    fail(child(path, key), "unknown key (expected one of: " + names + ")");
  }
}

const json& Reader::expect_array(const json& value, const std::string& path) const {
  if (!value.is_array()) fail(path, "expected an array, got " + describe(value));
  return value;
}

const json* Reader::find(const json& object, std::string_view key) {
  auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

int64_t Reader::integer(const json& value, const std::string& path, int64_t lo,
                        int64_t hi) const {
  const std::string expected =
      "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got ";
  if (!value.is_number_integer()) fail(path, expected + describe(value));
  if (value.is_number_unsigned() &&
      value.get<uint64_t>() > uint64_t(std::numeric_limits<int64_t>::max()))
    fail(path, expected + describe(value));
  const int64_t v = value.get<int64_t>();
  if (v < lo || v > hi) fail(path, expected + describe(value));
  return v;
}

double Reader::number(const json& value, const std::string& path, const Range& range) const {
  const std::string expected = "expected " + a_number(range) + ", got ";
  if (!value.is_number()) fail(path, expected + describe(value));
  const double v = value.get<double>();
  // Everything ends up in float: a value that overflows it is as bad as one out of range.
  if (!(std::fabs(v) <= double(FLT_MAX)) || !range.contains(v))
    fail(path, expected + describe(value));
  return v;
}

bool Reader::boolean(const json& value, const std::string& path) const {
  if (!value.is_boolean()) fail(path, "expected true or false, got " + describe(value));
  return value.get<bool>();
}

std::string Reader::string(const json& value, const std::string& path) const {
  if (!value.is_string()) fail(path, "expected a string, got " + describe(value));
  return value.get<std::string>();
}

size_t Reader::choice(const json& value, const std::string& path,
                      const std::vector<std::string_view>& names) const {
  std::string list;
  for (std::string_view name : names) list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
  if (value.is_string()) {
    size_t i = 0;
    for (std::string_view name : names) {
      if (value.get<std::string>() == name) return i;
      ++i;
    }
  }
  fail(path, "expected one of " + list + ", got " + describe(value));
}

glm::dvec3 Reader::vec3(const json& value, const std::string& path, const Range& range) const {
  if (!value.is_array() || value.size() != 3)
    fail(path, "expected an array of 3 numbers, got " + describe(value));
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) v[i] = number(value[size_t(i)], element(path, size_t(i)), range);
  return v;
}

glm::dvec3 Reader::scalar_or_vec3(const json& value, const std::string& path,
                                  const Range& range) const {
  if (value.is_number()) return glm::dvec3(number(value, path, range));
  if (value.is_array()) return vec3(value, path, range);
  fail(path, "expected " + a_number(range) + " or an array of 3 of them, got " + describe(value));
}

}  // namespace fastshade::json_path
