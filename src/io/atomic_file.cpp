#include "fastshade/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <string_view>
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

bool all_digits(std::string_view text) {
  return !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
}

}  // namespace

std::string temp_file_target(const std::string& file_name) {
  // "." TARGET ".tmp" PID "." COUNTER EXT, EXT being TARGET's extension (maybe empty).
  static constexpr std::string_view kTmp = ".tmp";
  if (file_name.empty() || file_name[0] != '.') return "";
  for (std::size_t at = file_name.rfind(kTmp); at != std::string::npos && at > 1;
       at = file_name.rfind(kTmp, at - 1)) {
    const std::string target = file_name.substr(1, at - 1);
    const std::string ext = fs::path(target).extension().string();
    const std::string_view rest = std::string_view(file_name).substr(at + kTmp.size());
    if (rest.size() < ext.size() || rest.substr(rest.size() - ext.size()) != ext) continue;
    const std::string_view numbers = rest.substr(0, rest.size() - ext.size());
    const std::size_t dot = numbers.find('.');
    if (dot != std::string_view::npos && all_digits(numbers.substr(0, dot)) &&
        all_digits(numbers.substr(dot + 1)))
      return target;
  }
  return "";
}

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
