// An AOV list as text ("depth,normal,triangle_id,object_id", or "all") and as an AovSet: the
// one place the names are read (render --aov, batch --aov, batch results and fingerprints).
#pragma once
#include <string>

#include "fastshade/image.h"

namespace fastshade {

// Throws InputError naming `key` for an empty list or an unknown name.
AovSet parse_aov_list(const std::string& text, const std::string& key = "--aov");
// The names of `aovs`, comma-separated, in the list's order: "depth,triangle_id".
std::string aov_list_text(const AovSet& aovs);

}  // namespace fastshade
