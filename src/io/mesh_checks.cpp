// File access, format by extension, text encoding: the checks every mesh format shares.
#include "io/mesh_checks.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <memory>
#include <system_error>

#include "fastshade/error.h"
#include "io/text_scan.h"

namespace fastshade::io {

namespace fs = std::filesystem;

const char* format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::Obj: return "OBJ";
    case MeshFormat::Off: return "OFF";
    case MeshFormat::Ply: return "PLY";
    case MeshFormat::Stl: return "STL";
  }
  return "?";
}

void fail(const fs::path& path, const std::string& problem) {
  // Escape only what would break the one-line rule; ordinary non-ASCII names stay readable.
  std::string where;
  for (const char c : path.string()) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      where += quote(std::string_view(&c, 1));
    } else {
      where += c;
    }
  }
  std::string what = problem;
  for (char& c : what) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  throw InputError(where, what);
}

std::string_view FileBytes::read_up_to(std::uintmax_t n) {
  n = std::min(n, size_);
  if (bytes_.size() < n) {
    const std::size_t have = bytes_.size();
    bytes_.resize(n);
    const std::size_t got = std::fread(bytes_.data() + have, 1, n - have, file_);
    if (got != n - have) {
      const int err = errno;
      fail(path_, std::string("read error after ") + std::to_string(have + got) + " of " +
                      std::to_string(size_) + " bytes" +
                      (std::ferror(file_) ? std::string(": ") + std::strerror(err) : ""));
    }
  }
  return std::string_view(bytes_).substr(0, n);
}

std::string_view FileBytes::head() { return read_up_to(64 * 1024); }
std::string_view FileBytes::all() { return read_up_to(size_); }

void check_no_nul(const fs::path& path, std::string_view text) {
  const auto nul = text.find('\0');
  if (nul != std::string_view::npos) {
    fail(path, "NUL byte at offset " + std::to_string(nul) +
                   " in text: mesh text must be ASCII or UTF-8 (is it UTF-16, or binary data?)");
  }
}

namespace {

MeshFormat format_from_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".stl") return MeshFormat::Stl;
  fail(path, (ext.empty() ? std::string("no file extension") : "unknown extension " + quote(ext)) +
                 ": expected .obj, .off, .ply or .stl");
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

Precheck precheck_mesh_file(const fs::path& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) fail(path, "no such file");
  if (ec) fail(path, "cannot access: " + ec.message());
  if (st.type() == fs::file_type::directory) fail(path, "is a directory, not a mesh file");
  if (st.type() != fs::file_type::regular) fail(path, "not a regular file");

  Precheck out;
  out.format = format_from_extension(path);

  errno = 0;
  const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) fail(path, std::string("cannot open for reading: ") + std::strerror(errno));
  out.file_size = fs::file_size(path, ec);
  if (ec) fail(path, "cannot get the file size: " + ec.message());
  if (out.file_size == 0) fail(path, "empty file");

  FileBytes bytes(path, file.get(), out.file_size);
  const std::string_view head = bytes.head();
  const bool utf16_bom =
      head.size() >= 2 && ((head[0] == '\xFF' && head[1] == '\xFE') ||
                            (head[0] == '\xFE' && head[1] == '\xFF'));
  const auto utf16 = [&] {
    fail(path, std::string("UTF-16 text (byte-order mark ") +
                   (head[0] == '\xFF' ? "FF FE" : "FE FF") +
                   "): save the file as ASCII or UTF-8");
  };

  switch (out.format) {
    case MeshFormat::Obj: {
      if (utf16_bom) utf16();
      const std::string_view text = bytes.all();
      check_no_nul(path, text);
      out.obj = scan_obj(path, text);
      break;
    }
    case MeshFormat::Off:
      if (utf16_bom) utf16();
      check_off(path, bytes, out);
      break;
    case MeshFormat::Ply:
      if (utf16_bom) utf16();
      check_ply(path, bytes, out);
      break;
    case MeshFormat::Stl:
      // A binary STL's 80-byte header may hold anything, so check_stl looks for a BOM only
      // when the file is not a binary STL by size.
      check_stl(path, bytes);
      break;
  }
  return out;
}

}  // namespace fastshade::io
