// Reading the spellings of include/fastshade/options.h: what the command line, config files
// and Python do with an option's text.
#include <iterator>
#include <string>
#include <type_traits>

#include "fastshade/error.h"
#include "fastshade/options.h"

namespace fastshade {

namespace {

// "a, b or c": the spellings an option accepts, for its error.
template <OptionEnum E>
std::string spellings_text() {
  std::string out;
  const auto& values = OptionSpellings<E>::kValues;
  const std::size_t count = std::size(values);
  for (std::size_t i = 0; i < count; ++i) {
    std::string name(values[i].second);
    if constexpr (std::is_same_v<E, BrdfKind>)
      if (values[i].first == BrdfKind::CosK) name += ":K";
    out += (i == 0 ? "" : i + 1 == count ? " or " : ", ") + name;
  }
  return out;
}

}  // namespace

template <OptionValue T>
T parse_option(std::string_view text, const std::string& where) {
  for (const auto& [value, name] : OptionSpellings<T>::kValues)
    if (text == name) return value;
  throw InputError(where, "unknown " + std::string(OptionSpellings<T>::kWhat) + " '" + std::string(text) +
                              "' (expected " + spellings_text<T>() + ")");
}

template ShadingMethod parse_option(std::string_view, const std::string&);
template Isa parse_option(std::string_view, const std::string&);
template PhongNormals parse_option(std::string_view, const std::string&);
template GouraudMode parse_option(std::string_view, const std::string&);
template SpecMethod parse_option(std::string_view, const std::string&);
template ClassifierRule parse_option(std::string_view, const std::string&);
template HiddenFaces parse_option(std::string_view, const std::string&);

template <>
BrdfChoice parse_option(std::string_view text, const std::string& where) {
  if (text.starts_with("cosk:")) {
    const std::string_view k = text.substr(5);
    if (k.size() != 1 || k[0] < '0' + kMinCosK || k[0] > '0' + kMaxCosK)
      throw InputError(where, "cosk takes a power K from " + std::to_string(kMinCosK) + " to " +
                                  std::to_string(kMaxCosK) + ", as in cosk:3 (got '" + std::string(text) + "')");
    return {BrdfKind::CosK, k[0] - '0'};
  }
  if (text == "cosk") throw InputError(where, "cosk takes a power K, as in cosk:3");
  for (const auto& [kind, name] : OptionSpellings<BrdfKind>::kValues)
    if (text == name) return {kind};
  throw InputError(where, "unknown BRDF '" + std::string(text) + "' (expected " + spellings_text<BrdfKind>() + ")");
}

}  // namespace fastshade
