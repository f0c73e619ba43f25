#include "io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <system_error>

#include "fastshade/error.h"

namespace fastshade {
namespace fs = std::filesystem;

namespace {

// ".NAME.tmp<pid>.<n>EXT": unique within and across processes.
fs::path temp_path_for(const fs::path& target) {
  static std::atomic<unsigned long> counter{0};
  // Built by append: "." + std::string&& trips GCC 12's false -Wrestrict (GCC bug 105651).
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp";
  name += std::to_string(::getpid());
  name += '.';
  name += std::to_string(counter.fetch_add(1));
  name += target.extension().string();
  const fs::path dir = target.parent_path();
  return (dir.empty() ? fs::path(".") : dir) / name;
}

}  // namespace

TempFile::TempFile(const fs::path& target) : path_(temp_path_for(target)), target_(target) {}

TempFile::~TempFile() {
  if (!path_.empty()) {
    std::error_code ec;
    fs::remove(path_, ec);
  }
}

void TempFile::commit() {
  std::error_code ec;
  fs::rename(path_, target_, ec);
  if (ec) throw InputError(target_.string(), "cannot move the written file into place: " + ec.message());
  path_.clear();
}

void write_text_file(const fs::path& target, const std::string& text) {
  TempFile temp(target);
  {
    std::ofstream out(temp.path(), std::ios::binary);
    out << text;
    out.flush();
    if (!out) throw InputError(target.string(), "cannot write file");
  }
  temp.commit();
}

}  // namespace fastshade
