#include "fastshade/render_config.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <variant>

#include "fastshade/error.h"
#include "io/json_file.h"
#include "io/json_path.h"

namespace fastshade {

namespace {

using json_path::child;
using json_path::Reader;
using nlohmann::json;

// Reads one option's value by its type and spelling; ranges are left to validate().
void read_option(const Reader& r, const json& value, const RenderConfigKey& key, RenderOptions& o) {
  const std::string path = child("options", key.key);
  const std::string where = r.source() + ": " + path;  // as Reader::fail names it
  std::visit(
      [&](auto member) {
        using T = std::remove_reference_t<decltype(o.*member)>;
        if constexpr (std::is_same_v<T, int>)
          o.*member = int(r.integer(value, path, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
        else if constexpr (std::is_same_v<T, double>)
          o.*member = r.number(value, path, json_path::kAnyNumber);
        else if constexpr (std::is_same_v<T, bool>)
          o.*member = r.boolean(value, path);
        else
          o.*member = parse_option<T>(r.string(value, path), where);
      },
      key.member);
}

// A value as the file spells it.
template <class T>
nlohmann::ordered_json option_json(const T& value) {
  if constexpr (std::is_arithmetic_v<T>)
    return value;
  else
    return std::string(option_name(value));
}

// validate() names a flag ("--tile: ..."); in a config the culprit is the flag's key.
void validate_keys(const Reader& r, const RenderOptions& options) {
  try {
    validate(options);
  } catch (const InputError& e) {
    const std::string message = e.what();
    const std::size_t colon = message.find(": ");
    const std::string flag = message.substr(0, colon);
    for (const RenderConfigKey& key : kRenderConfigKeys)
      if (key.flag == flag) r.fail(child("options", key.key), message.substr(colon + 2));
    r.fail("options", message);
  }
}

}  // namespace

void copy_option(const RenderConfigKey& key, const RenderOptions& from, RenderOptions& to) {
  std::visit([&](auto member) { to.*member = from.*member; }, key.member);
}

RenderConfig parse_render_config(const std::string& text, const std::string& source) {
  const json root = json_path::parse(text, source);
  const Reader r(source);
  r.expect_object(root, "", {"options", "provenance"});
  const json* options = Reader::find(root, "options");
  if (!options) r.fail("options", "missing (the render options, e.g. {\"method\": \"auto\", \"tile\": 32})");
  std::vector<std::string_view> names;
  for (const RenderConfigKey& key : kRenderConfigKeys) names.push_back(key.key);
  r.expect_object(*options, "options", names);
  if (const json* provenance = Reader::find(root, "provenance"); provenance && !provenance->is_object())
    r.fail("provenance", "expected an object, got " + json_path::describe(*provenance));

  RenderConfig config;
  for (const RenderConfigKey& key : kRenderConfigKeys) {
    if (const json* value = Reader::find(*options, key.key)) {
      read_option(r, *value, key, config.options);
      config.keys.push_back(key.key);
    }
  }
  validate_keys(r, config.options);
  return config;
}

RenderConfig load_render_config(const std::filesystem::path& path) {
  return parse_render_config(read_json_file_text(path, "config file"), path.string());
}

std::string render_config_text(const RenderOptions& options, std::span<const std::string_view> keys,
                               const nlohmann::ordered_json& provenance) {
  nlohmann::ordered_json values = nlohmann::ordered_json::object();
  for (const RenderConfigKey& key : kRenderConfigKeys) {
    if (std::find(keys.begin(), keys.end(), key.key) == keys.end()) continue;
    std::visit([&](auto member) { values[std::string(key.key)] = option_json(options.*member); }, key.member);
  }
  nlohmann::ordered_json file = {{"options", values}};
  if (!provenance.is_null()) file["provenance"] = provenance;
  return file.dump(2) + "\n";
}

}  // namespace fastshade
