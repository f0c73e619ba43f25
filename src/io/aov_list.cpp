#include "fastshade/aov_list.h"

#include <sstream>

#include "fastshade/error.h"

namespace fastshade {

namespace {

struct AovName {
  const char* name;
  bool AovSet::*flag;
};
constexpr AovName kAovNames[] = {{"depth", &AovSet::depth},
                                 {"normal", &AovSet::normal},
                                 {"triangle_id", &AovSet::triangle_id},
                                 {"object_id", &AovSet::object_id}};

}  // namespace

AovSet parse_aov_list(const std::string& text, const std::string& key) {
  AovSet aovs;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) {
    bool known = name == "all";
    for (const AovName& n : kAovNames)
      if (name == n.name || name == "all") {
        aovs.*n.flag = true;
        known = true;
      }
    if (!known)
      throw InputError(key, "unknown output '" + name + "' (expected depth, normal, triangle_id, object_id or all)");
  }
  if (!aovs.any()) throw InputError(key, "expected a list of depth, normal, triangle_id, object_id or all");
  return aovs;
}

std::string aov_list_text(const AovSet& aovs) {
  std::string text;
  for (const AovName& n : kAovNames)
    if (aovs.*n.flag) text += (text.empty() ? "" : ",") + std::string(n.name);
  return text;
}

}  // namespace fastshade
