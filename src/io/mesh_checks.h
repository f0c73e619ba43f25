// Checks a mesh file before OpenMesh sees it. OpenMesh trusts its input: a header that lies
// about counts makes it allocate without bound (std::bad_alloc) or loop for billions of faces,
// an OBJ face index out of range is written through as a vertex handle, UTF-16 text reads as an
// empty mesh. Everything here is cheap (a header, or one pass over a text file) and throws
// InputError with one line "PATH: problem".
#pragma once
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace fastshade::io {

enum class MeshFormat { Obj, Off, Ply, Stl };

const char* format_name(MeshFormat format);

// Throws InputError(path, problem); the path is printed with control characters escaped so the
// message is always one line.
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem);

// What one pass over an OBJ file found; every index in it has been checked.
struct ObjScan {
  std::size_t positions = 0;           // `v` lines
  std::size_t triangles = 0;           // fan triangles of the faces with >= 3 distinct vertices
  std::size_t degenerate_faces = 0;    // faces with < 3 distinct vertices: OpenMesh drops them
};

struct Precheck {
  MeshFormat format = MeshFormat::Obj;
  std::uintmax_t file_size = 0;
  // OFF and PLY: the counts the header declares (checked against the file size).
  std::optional<std::uint64_t> declared_vertices;
  std::optional<std::uint64_t> declared_faces;
  std::optional<ObjScan> obj;  // OBJ only
};

// Access (exists, not a directory, regular, readable, not empty), extension, encoding and the
// format's header or body checks listed above. Throws InputError.
Precheck precheck_mesh_file(const std::filesystem::path& path);

// A file's bytes, read lazily: binary formats need only their header, text formats all of it.
class FileBytes {
 public:
  FileBytes(const std::filesystem::path& path, std::FILE* file, std::uintmax_t size)
      : path_(path), file_(file), size_(size) {}
  std::uintmax_t size() const { return size_; }
  std::string_view head();  // the first min(size, 64 KiB) bytes
  std::string_view all();   // the whole file; views from head() are invalid after it

 private:
  std::string_view read_up_to(std::uintmax_t n);
  const std::filesystem::path& path_;
  std::FILE* file_;
  std::uintmax_t size_;
  std::string bytes_;
};

// Format-specific parts of precheck_mesh_file.
ObjScan scan_obj(const std::filesystem::path& path, std::string_view text);
void check_off(const std::filesystem::path& path, FileBytes& file, Precheck& out);
void check_ply(const std::filesystem::path& path, FileBytes& file, Precheck& out);
void check_stl(const std::filesystem::path& path, FileBytes& file);

// Every whitespace-separated token of an ASCII OFF/PLY body must be a finite number (OpenMesh
// reads these bodies with `stream >> float`, which turns "nan" or a comment into silently wrong
// data). Returns the number of tokens. `first_line` is the body's line number in the file.
std::uint64_t scan_numeric_body(const std::filesystem::path& path, std::string_view body,
                                std::size_t first_line);

// Rejects NUL bytes in text (UTF-16 without a byte-order mark, or binary data).
void check_no_nul(const std::filesystem::path& path, std::string_view text);

}  // namespace fastshade::io
