#include "io/json_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "fastshade/error.h"

namespace fastshade {

std::string read_json_file_text(const std::filesystem::path& path, std::string_view kind) {
  const std::string source = path.string();
  const std::string expected = "expected a " + std::string(kind) + " (JSON)";
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw InputError(source, "cannot access: " + ec.message());
  if (!std::filesystem::exists(status)) throw InputError(source, "no such " + std::string(kind));
  if (std::filesystem::is_directory(status)) throw InputError(source, "is a directory, " + expected);
  if (!std::filesystem::is_regular_file(status))
    throw InputError(source, "not a regular file, " + expected);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(source, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(source, "read error");
  return text.str();
}

}  // namespace fastshade
