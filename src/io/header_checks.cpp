// OFF, PLY and STL checks: header counts against the file size, ASCII bodies all numbers.
//
// Lower bounds on the data a header's counts need, so a lying header is caught before OpenMesh
// reserves memory for it (it does, with the raw counts) or loops over billions of records:
// - binary: each record needs the sum of its scalar property sizes, plus a list's count field;
//   a face's vertex list also needs 3 indices (a face with fewer is rejected anyway), so a PLY
//   `list uchar int` face needs >= 1 + 3*4 = 13 bytes and an OFF BINARY face >= 4 + 3*4 = 16.
// - ASCII: each value is a token of >= 1 character, and tokens are separated by >= 1
//   whitespace character, so T tokens need >= 2*T - 1 bytes. An OFF vertex is >= 3 tokens
//   (>= 6 bytes with its separator), an OFF face >= 4 ("3 0 1 2", >= 8 bytes), a PLY record
//   one token per scalar, 1 per list count and 3 more for a face's vertex list.
#include <algorithm>
#include <cctype>
#include <cstring>
#include <string>
#include <vector>

#include "io/mesh_checks.h"
#include "io/text_scan.h"

namespace fastshade::io {

namespace fs = std::filesystem;

namespace {

struct Cursor {
  std::string_view text;
  std::size_t pos = 0;
  std::size_t line_number = 0;  // of the last line returned
  // The next line without its '\n' (and '\r'); false at the end.
  bool next_line(std::string_view& line) {
    if (pos >= text.size()) return false;
    std::size_t end = text.find('\n', pos);
    const bool complete = end != std::string_view::npos;
    if (!complete) end = text.size();
    line = text.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = complete ? end + 1 : end;
    ++line_number;
    return true;
  }
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  for_each_token(line, [&](std::string_view tok) {
    out.push_back(tok);
    return true;
  });
  return out;
}

// "header declares 8 vertices and 353535235358 faces but the file has 309 bytes ..."
[[noreturn]] void fail_counts(const fs::path& path, uint64_t vertices, uint64_t faces,
                              std::uintmax_t file_size, double needed_bytes) {
  char needed[64];
  std::snprintf(needed, sizeof needed, "%.0f", needed_bytes);
  fail(path, "header declares " + std::to_string(vertices) + " vertices and " +
                 std::to_string(faces) + " faces but the file has " + std::to_string(file_size) +
                 " bytes (that many need at least " + needed + ")");
}

bool read_u32_le(std::string_view data, std::size_t at, uint32_t& out) {
  if (data.size() < at + 4) return false;
  const auto* b = reinterpret_cast<const unsigned char*>(data.data() + at);
  out = uint32_t{b[0]} | uint32_t{b[1]} << 8 | uint32_t{b[2]} << 16 | uint32_t{b[3]} << 24;
  return true;
}

}  // namespace

std::uint64_t scan_numeric_body(const fs::path& path, std::string_view body,
                                std::size_t first_line) {
  uint64_t count = 0;
  std::size_t line = first_line;
  std::size_t i = 0;
  while (i < body.size()) {
    const char c = body[i];
    if (is_space(c)) {
      if (c == '\n') ++line;
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < body.size() && !is_space(body[i])) ++i;
    const std::string_view tok = body.substr(start, i - start);
    double value = 0.0;
    switch (parse_number(tok, value)) {
      case NumberStatus::NotANumber:
        fail(path, "line " + std::to_string(line) + ": expected a number, found " + quote(tok));
      case NumberStatus::NotFinite:
        fail(path, "line " + std::to_string(line) + ": non-finite number " + quote(tok));
      case NumberStatus::Ok:
        break;
    }
    ++count;
  }
  return count;
}

// OpenMesh reads a binary OFF face as its vertex count n, then n indices one at a time with
// no end-of-file check: a count of 4e9 in a small file loops 4e9 times and grows a vector to
// 16 GB. Every face's list must fit in the bytes left after it, walked the way OpenMesh walks
// them (a face's colour, with the C prefix, is read only when the caller asks for face colours,
// and load_mesh does not).
void check_off_binary_faces(const fs::path& path, std::string_view data, uint64_t at, uint32_t faces) {
  for (uint32_t f = 0; f < faces; ++f) {
    uint32_t n = 0;
    if (at > data.size() || !read_u32_le(data, static_cast<std::size_t>(at), n)) {
      fail(path, "truncated: OFF BINARY face " + std::to_string(f) + " of " + std::to_string(faces) +
                     " starts past the end of the file");
    }
    const uint64_t left = data.size() - at - 4;
    if (uint64_t{n} * 4 > left) {
      fail(path, "OFF BINARY face " + std::to_string(f) + " lists " + std::to_string(n) +
                     " vertices but only " + std::to_string(left) + " bytes follow");
    }
    at += 4 + uint64_t{n} * 4;
  }
}

// Whether the token is a plain run of decimal digits (no sign, point or exponent): what
// OpenMesh's `>> unsigned` reads whole.
bool all_digits(std::string_view tok) {
  return !tok.empty() && std::all_of(tok.begin(), tok.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The body's numbers one at a time, as a stream reads them (`>>` crosses lines), with
// getline's "the rest of this line".
class TokenWalk {
 public:
  explicit TokenWalk(std::string_view body) : lines_{body} {}
  bool next(std::string_view& tok) {
    while (rest_.empty()) {
      if (!lines_.next_line(rest_)) return false;
      rest_ = trim(rest_);
    }
    std::size_t end = 0;
    while (end < rest_.size() && !is_space(rest_[end])) ++end;
    tok = rest_.substr(0, end);
    rest_ = trim(rest_.substr(end));
    ++consumed_;
    return true;
  }
  void skip_rest_of_line() {
    for_each_token(rest_, [&](std::string_view) { return ++consumed_, true; });
    rest_ = {};
  }
  uint64_t consumed() const { return consumed_; }
  std::size_t line_number() const { return lines_.line_number; }

 private:
  Cursor lines_;
  std::string_view rest_;
  uint64_t consumed_ = 0;
};

// The same for an ASCII OFF, walked as OpenMesh reads it: the three counts, then per vertex its
// 3 (with normals 6) numbers and the rest of that line (colours, texture coordinates), then per
// face its vertex count n and n indices read as `unsigned` (with colours, the rest of the line).
// A count or index that is not a whole number ("-1" reads as 4294967295, "1.5" fails the stream
// and leaves the last count standing) or n past the numbers left is refused: OpenMesh would
// loop n times. `total`: the body's numbers.
void check_off_ascii_faces(const fs::path& path, std::string_view body, uint64_t total, uint64_t vertices,
                           bool normals, uint64_t faces, bool colors) {
  TokenWalk walk{body};
  std::string_view tok;
  for (int i = 0; i < 3; ++i)
    if (!walk.next(tok)) return;  // the truncation checks above speak for these
  for (uint64_t v = 0; v < vertices; ++v) {
    for (int i = 0; i < (normals ? 6 : 3); ++i)
      if (!walk.next(tok)) return;
    walk.skip_rest_of_line();
  }
  // An index may be negative (it reads as a huge one, which the range check refuses later); a
  // count may not.
  const auto whole = [&](std::string_view t, uint64_t face, const char* what, bool sign_allowed) {
    const std::string_view digits = sign_allowed && t.starts_with('-') ? t.substr(1) : t;
    int64_t value = -1;
    if (!all_digits(digits) ||
        !parse_integer(t, value) || value > int64_t{UINT32_MAX} || value < -int64_t{UINT32_MAX}) {
      fail(path, "line " + std::to_string(1 + walk.line_number()) + ": face " + std::to_string(face) + "'s " + what +
                     " is " + quote(t) + ", not a whole number");
    }
    return uint64_t(value);
  };
  for (uint64_t f = 0; f < faces; ++f) {
    if (!walk.next(tok)) return;
    const uint64_t n = whole(tok, f, "vertex count", false);
    if (n > total - walk.consumed()) {
      fail(path, "line " + std::to_string(1 + walk.line_number()) + ": face " + std::to_string(f) + " lists " +
                     std::to_string(n) + " vertices but only " + std::to_string(total - walk.consumed()) +
                     " numbers follow");
    }
    for (uint64_t j = 0; j < n; ++j) {
      if (!walk.next(tok)) return;
      whole(tok, f, "vertex index", true);
    }
    if (colors) walk.skip_rest_of_line();
  }
}

void check_off(const fs::path& path, FileBytes& file, Precheck& out) {
  const std::string_view head = file.head();
  Cursor cur{head};
  std::string_view first;
  cur.next_line(first);
  // [ST][C][N][4][n]OFF [BINARY], as OpenMesh's reader accepts it.
  std::string_view magic = trim(first);
  bool texcoords = false, normals = false, colors = false;
  if (magic.substr(0, 2) == "ST") texcoords = true, magic.remove_prefix(2);
  if (magic.substr(0, 1) == "C") colors = true, magic.remove_prefix(1);
  if (magic.substr(0, 1) == "N") normals = true, magic.remove_prefix(1);
  if (magic.substr(0, 1) == "4" || magic.substr(0, 1) == "n") {
    fail(path, "4OFF / nOFF (4-D or n-D vertices) is not supported");
  }
  if (magic.substr(0, 3) != "OFF") {
    fail(path, "not an OFF file: the first line is " + quote(first) + ", expected OFF");
  }
  const std::string_view rest = trim(magic.substr(3));
  const bool binary = rest == "BINARY";
  if (!binary && !rest.empty()) {
    fail(path, "unexpected " + quote(rest) +
                   " after OFF on the first line (the counts go on the next line)");
  }
  const uint64_t per_vertex = 3 + (normals ? 3 : 0) + (texcoords ? 2 : 0);  // values

  if (binary) {
    uint32_t nv = 0, nf = 0, ne = 0;
    if (!read_u32_le(head, cur.pos, nv) || !read_u32_le(head, cur.pos + 4, nf) ||
        !read_u32_le(head, cur.pos + 8, ne)) {
      fail(path, "OFF BINARY header ends before its vertex, face and edge counts");
    }
    const double needed = double(cur.pos) + 12.0 + double(nv) * double(4 * per_vertex) +
                          double(nf) * 16.0;
    if (needed > double(file.size())) fail_counts(path, nv, nf, file.size(), needed);
    // A vertex's colour (C prefix) is three 4-byte values, always read.
    check_off_binary_faces(path, file.all(), cur.pos + 12 + uint64_t{nv} * 4 * (per_vertex + (colors ? 3 : 0)), nf);
    out.declared_vertices = nv;
    out.declared_faces = nf;
    return;
  }

  const std::string_view text = file.all();
  check_no_nul(path, text);
  const std::string_view body = text.substr(cur.pos);
  // The three counts: OpenMesh reads them with `>> unsigned`, comments are not supported.
  uint64_t counts[3] = {0, 0, 0};
  int found = 0;
  Cursor counts_cur{body};
  std::string_view line;
  while (found < 3 && counts_cur.next_line(line)) {
    for_each_token(line, [&](std::string_view tok) {
      int64_t value = -1;
      if (!parse_integer(tok, value) || value < 0) {
        fail(path, "line " + std::to_string(1 + counts_cur.line_number) +
                       ": expected the vertex, face and edge counts, found " + quote(tok));
      }
      counts[found++] = static_cast<uint64_t>(value);
      return found < 3;
    });
  }
  if (found < 3) fail(path, "OFF header ends before its vertex, face and edge counts");
  const double tokens_needed = 3.0 + double(counts[0]) * double(per_vertex) + double(counts[1]) * 4.0;
  const double bytes_needed = double(cur.pos) + 2.0 * tokens_needed - 1.0;
  if (bytes_needed > double(file.size())) {
    fail_counts(path, counts[0], counts[1], file.size(), bytes_needed);
  }
  const uint64_t tokens_found = scan_numeric_body(path, body, 2);
  if (double(tokens_found) < tokens_needed) {
    fail(path, "truncated: the header declares " + std::to_string(counts[0]) + " vertices and " +
                   std::to_string(counts[1]) + " faces, which need at least " +
                   std::to_string(uint64_t(tokens_needed)) + " numbers, but the file has " +
                   std::to_string(tokens_found));
  }
  check_off_ascii_faces(path, body, tokens_found, counts[0], normals, counts[1], colors);
  out.declared_vertices = counts[0];
  out.declared_faces = counts[1];
}

struct PlyProperty {
  bool list = false;
  uint64_t count_size = 0;  // a list's count, in bytes
  uint64_t size = 0;        // a scalar's, or a list item's, in bytes
  bool integer = false;     // a scalar of an integer type
  std::string name;
};

// The vertex properties OpenMesh reads as floats: in a binary file it converts only float and
// double to them, and for any other type prints lines of its own to stderr and fails.
bool read_as_float(std::string_view vertex_property) {
  for (std::string_view name : {"x", "y", "z", "nx", "ny", "nz", "u", "v", "s", "t", "texture_u", "texture_v"})
    if (vertex_property == name) return true;
  return false;
}
struct PlyElement {
  std::string name;
  uint64_t count = 0;
  uint64_t min_bytes = 0;   // binary
  uint64_t min_tokens = 0;  // ASCII
  bool has_xyz[3] = {false, false, false};
  std::vector<PlyProperty> properties;
};

// OpenMesh reads a list's count and then that many items with no end-of-file check: a count of
// 2^31 (or, in ASCII, one that overflows and fails the stream) loops as many times and grows a
// vector to gigabytes. Every list must fit in what follows it, walked record by record.
void check_ply_ascii_lists(const fs::path& path, std::string_view body, std::size_t header_lines, uint64_t total,
                           const std::vector<PlyElement>& elements) {
  TokenWalk walk{body};
  std::string_view tok;
  for (const PlyElement& e : elements) {
    for (uint64_t r = 0; r < e.count; ++r) {
      for (const PlyProperty& p : e.properties) {
        if (!walk.next(tok)) return;  // the truncation check speaks for this
        if (!p.list) continue;
        int64_t n = -1;
        if (!all_digits(tok) ||
            !parse_integer(tok, n) || uint64_t(n) > total - walk.consumed()) {
          fail(path, "line " + std::to_string(header_lines + walk.line_number()) + ": " + e.name + " " + std::to_string(r) +
                         " has a list of " + quote(tok) + " items, but only " +
                         std::to_string(total - walk.consumed()) + " numbers follow");
        }
        for (int64_t j = 0; j < n; ++j)
          if (!walk.next(tok)) return;
      }
    }
  }
}

void check_ply_binary_lists(const fs::path& path, std::string_view body, bool big_endian,
                            const std::vector<PlyElement>& elements) {
  uint64_t at = 0;
  for (const PlyElement& e : elements) {
    for (uint64_t r = 0; r < e.count; ++r) {
      for (const PlyProperty& p : e.properties) {
        if (!p.list) {
          at += p.size;
          continue;
        }
        if (at + p.count_size > body.size()) return;  // the size check speaks for this
        uint64_t n = 0;
        for (uint64_t i = 0; i < p.count_size; ++i) {
          const auto byte = static_cast<unsigned char>(body[at + (big_endian ? i : p.count_size - 1 - i)]);
          n = n << 8 | byte;
        }
        at += p.count_size;
        if (n > (body.size() - at) / p.size) {
          fail(path, e.name + " " + std::to_string(r) + " has a list of " + std::to_string(n) + " items, but only " +
                         std::to_string(body.size() - at) + " bytes follow");
        }
        at += n * p.size;
      }
    }
  }
}

void check_ply(const fs::path& path, FileBytes& file, Precheck& out) {
  const std::string_view head = file.head();
  Cursor cur{head};
  std::string_view line;
  cur.next_line(line);
  if (trim(line) != "ply") {
    fail(path, "not a PLY file: the first line is " + quote(line) + ", expected ply");
  }

  std::vector<PlyElement> elements;
  std::string format;
  bool ended = false;
  const auto scalar_size = [&](std::string_view type) -> uint64_t {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" ||
        type == "float" || type == "float32") {
      return 4;
    }
    if (type == "double" || type == "float64") return 8;
    fail(path, "line " + std::to_string(cur.line_number) + ": unknown PLY property type " +
                   quote(type));
  };
  while (cur.next_line(line)) {
    const auto tok = tokens(line);
    if (tok.empty()) continue;
    const auto at_line = [&] { return "line " + std::to_string(cur.line_number) + ": "; };
    if (tok[0] == "end_header") {
      if (tok.size() != 1) fail(path, at_line() + "expected 'end_header' alone, found " + quote(line));
      ended = true;
      break;
    }
    if (tok[0] == "format") {
      if (tok.size() < 2 || (tok[1] != "ascii" && tok[1] != "binary_little_endian" &&
                             tok[1] != "binary_big_endian")) {
        fail(path, at_line() + "unknown PLY format " + quote(line));
      }
      // OpenMesh reads the version with `>> float`; one that is not a float (a word, or a number
      // past float's range) leaves its stream failed and its header loop spinning forever. The
      // format has one version: 1.0.
      if (tok.size() != 3 || tok[2] != "1.0") {
        fail(path, at_line() + "expected 'format " + std::string(tok[1]) + " 1.0', found " + quote(line));
      }
      format = std::string(tok[1]);
    } else if (tok[0] == "element") {
      int64_t count = -1;
      if (tok.size() != 3 || !parse_integer(tok[2], count) || count < 0) {
        fail(path, at_line() + "expected 'element NAME COUNT', found " + quote(line));
      }
      elements.push_back({std::string(tok[1]), static_cast<uint64_t>(count)});
    } else if (tok[0] == "property") {
      if (elements.empty()) fail(path, at_line() + "property before any element");
      PlyElement& e = elements.back();
      if (tok.size() >= 2 && tok[1] == "list") {
        if (tok.size() != 5) {
          fail(path, at_line() + "expected 'property list COUNT_TYPE TYPE NAME', found " +
                         quote(line));
        }
        const uint64_t count_size = scalar_size(tok[2]);
        const uint64_t item_size = scalar_size(tok[3]);
        const bool face_vertices =
            e.name == "face" && (tok[4] == "vertex_indices" || tok[4] == "vertex_index");
        e.min_bytes += count_size + (face_vertices ? 3 * item_size : 0);
        e.min_tokens += 1 + (face_vertices ? 3 : 0);
        e.properties.push_back({true, count_size, item_size});
      } else {
        if (tok.size() != 3) {
          fail(path, at_line() + "expected 'property TYPE NAME', found " + quote(line));
        }
        e.min_bytes += scalar_size(tok[1]);
        e.min_tokens += 1;
        const bool integer = tok[1] != "float" && tok[1] != "float32" && tok[1] != "double" && tok[1] != "float64";
        e.properties.push_back({false, 0, scalar_size(tok[1]), integer, std::string(tok[2])});
        for (int axis = 0; axis < 3; ++axis) {
          if (tok[2] == std::string_view("xyz" + axis, 1)) e.has_xyz[axis] = true;
        }
      }
    } else if (tok[0] != "comment" && tok[0] != "obj_info") {
      // OpenMesh reads the header as a stream of words: an unknown one (or a line of the wrong
      // length) puts its reading out of step with the lines, and one that never meets
      // end_header loops forever at the end of the file.
      fail(path, at_line() + "unknown PLY header line " + quote(line));
    }
  }
  if (!ended) {
    check_no_nul(path, head);
    fail(path, "PLY header has no end_header line in its first " +
                   std::to_string(head.size()) + " bytes");
  }
  check_no_nul(path, head.substr(0, cur.pos));
  if (format.empty()) fail(path, "PLY header has no format line");

  if (format != "ascii") {
    for (const PlyElement& e : elements)
      for (const PlyProperty& p : e.properties)
        if (e.name == "vertex" && !p.list && p.integer && read_as_float(p.name)) {
          fail(path, "the binary PLY vertex property " + quote(p.name) +
                         " is an integer type; OpenMesh reads it only as float or double");
        }
  }
  uint64_t vertices = 0, faces = 0;
  double min_bytes = 0.0, min_tokens = 0.0;
  for (const PlyElement& e : elements) {
    if (e.name == "vertex") {
      vertices = e.count;
      if (!(e.has_xyz[0] && e.has_xyz[1] && e.has_xyz[2])) {
        fail(path, "the PLY vertex element lacks an x, y or z property");
      }
    }
    if (e.name == "face") faces = e.count;
    // A record of no properties takes no bytes, so no file size bounds the count; OpenMesh
    // would reserve memory for all of them (100 M faces: 9.6 GB) and loop over each.
    if (e.count > 0 && e.min_tokens == 0) {
      fail(path, "the PLY element " + quote(e.name) + " declares " + std::to_string(e.count) +
                     " records but no properties");
    }
    min_bytes += double(e.count) * double(e.min_bytes);
    min_tokens += double(e.count) * double(e.min_tokens);
  }
  const double body_bytes = double(file.size()) - double(cur.pos);
  if (format == "ascii") {
    if (min_tokens > 0 && 2.0 * min_tokens - 1.0 > body_bytes) {
      fail_counts(path, vertices, faces, file.size(), double(cur.pos) + 2.0 * min_tokens - 1.0);
    }
    const std::string_view text = file.all();
    check_no_nul(path, text);
    const uint64_t found = scan_numeric_body(path, text.substr(cur.pos), cur.line_number + 1);
    if (double(found) < min_tokens) {
      fail(path, "truncated: the header declares " + std::to_string(vertices) +
                     " vertices and " + std::to_string(faces) + " faces, which need at least " +
                     std::to_string(uint64_t(min_tokens)) + " numbers, but the file has " +
                     std::to_string(found));
    }
    check_ply_ascii_lists(path, text.substr(cur.pos), cur.line_number, found, elements);
  } else {
    if (min_bytes > body_bytes) fail_counts(path, vertices, faces, file.size(), double(cur.pos) + min_bytes);
    const std::size_t body_at = cur.pos;
    check_ply_binary_lists(path, file.all().substr(body_at), format == "binary_big_endian", elements);
  }
  out.declared_vertices = vertices;
  out.declared_faces = faces;
}

void check_stl(const fs::path& path, FileBytes& file) {
  const std::string_view head = file.head();
  // OpenMesh's rule: binary exactly when 84 + 50 * (triangle count at byte 80) is the size.
  uint32_t triangles = 0;
  const bool has_count = read_u32_le(head, 80, triangles);
  const uint64_t binary_size = 84 + 50 * uint64_t{triangles};
  if (has_count && binary_size == file.size()) return;

  if (head.size() >= 2 && ((head[0] == '\xFF' && head[1] == '\xFE') ||
                           (head[0] == '\xFE' && head[1] == '\xFF'))) {
    fail(path, std::string("UTF-16 text (byte-order mark ") +
                   (head[0] == '\xFF' ? "FF FE" : "FE FF") + "): save the file as ASCII or UTF-8");
  }
  std::string_view start = trim(head.substr(0, 64));
  std::string first(start.substr(0, 5));
  for (char& c : first) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (first != "solid") {
    fail(path, "neither a binary STL (" +
                   (has_count ? "its header says " + std::to_string(triangles) +
                                    " triangles, which need " + std::to_string(binary_size) +
                                    " bytes, but the file has " + std::to_string(file.size())
                              : "shorter than the 84-byte header") +
                   ") nor an ASCII STL (it does not start with 'solid')");
  }
  const std::string_view text = file.all();
  check_no_nul(path, text);
  // OpenMesh reads `vertex x y z` with `stream >> float`: "nan" would leave stale values.
  Cursor cur{text};
  std::string_view line;
  while (cur.next_line(line)) {
    const auto tok = tokens(line);
    if (tok.empty() || (tok[0] != "vertex" && tok[0] != "VERTEX")) continue;
    bool ok = tok.size() >= 4;
    for (std::size_t i = 1; ok && i < 4; ++i) {
      double value = 0.0;
      ok = parse_number(tok[i], value) == NumberStatus::Ok;
    }
    if (!ok) {
      fail(path, "line " + std::to_string(cur.line_number) +
                     ": a vertex needs 3 finite numbers, found " + quote(trim(line)));
    }
  }
}

}  // namespace fastshade::io
