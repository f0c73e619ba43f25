// Reading a JSON input file's text, with one-line errors that name the file.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

namespace fastshade {

// The whole file. Throws InputError naming `path` if it is missing, a directory, not a regular
// file or unreadable; `kind` says what was expected ("scene file", "config file").
std::string read_json_file_text(const std::filesystem::path& path, std::string_view kind);

}  // namespace fastshade
