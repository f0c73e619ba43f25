// Reading a scene file's text, with the checks and messages load_scene gives (internal to io/
// and the program: a batch template is read the same way).
#pragma once
#include <filesystem>
#include <string>

namespace fastshade {

// Throws InputError("PATH: problem") for a missing, unreadable or non-regular file.
std::string read_scene_file(const std::filesystem::path& path);

}  // namespace fastshade
