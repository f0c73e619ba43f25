// Outputs appear whole or not at all: write a temporary file beside the target, then rename.
#pragma once
#include <filesystem>
#include <string>

namespace fastshade {

// ".NAME.tmp<pid>.<n>EXT" beside the target: hidden, unique within and across processes, and
// ending in the real extension so format-sniffing writers (OpenImageIO) pick the same format.
std::filesystem::path temp_path_for(const std::filesystem::path& target);

// Removes the temporary file unless committed: every failure path, exceptions included.
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

// Writes text to `target` through a TempFile; throws InputError naming it on failure.
void write_text_file(const std::filesystem::path& target, const std::string& text);

}  // namespace fastshade
