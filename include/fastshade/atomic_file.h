// Outputs appear whole or not at all: write a temporary file beside the target, then rename.
#pragma once
#include <filesystem>
#include <string>

namespace fastshade {

// A hidden temporary file beside the target, ending in the target's extension (so format-
// sniffing writers such as OpenImageIO pick the same format); removed unless committed: every
// failure path, exceptions included.
class TempFile {
 public:
  explicit TempFile(const std::filesystem::path& target);
  ~TempFile();
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::filesystem::path& path() const { return path_; }
  // Renames the temporary file onto the target; throws InputError naming the target on failure.
  void commit();

 private:
  std::filesystem::path path_, target_;
};

// The name of the target a TempFile's file name belongs to ("a.png" for ".a.png.tmp123.4.png"),
// or "" if `file_name` is not one: lets a program find what a killed run left behind.
std::string temp_file_target(const std::string& file_name);

// Writes text to `target` through a TempFile; throws InputError naming it on failure.
void write_text_file(const std::filesystem::path& target, const std::string& text);

}  // namespace fastshade
