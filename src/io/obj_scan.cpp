// One pass over an OBJ file, before OpenMesh reads it. OpenMesh's OBJ reader skips a `v` line it
// cannot parse (so later indices shift), skips faces with bad indices, and for `f 1//9` with no
// 9th normal writes through an invalid vertex handle. Here every number and index is checked,
// with the line number in the message.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "io/mesh_checks.h"
#include "io/text_scan.h"

namespace fastshade::io {

namespace {

struct Line {
  const std::filesystem::path& path;
  std::size_t number;
  [[noreturn]] void fail(const std::string& problem) const {
    io::fail(path, "line " + std::to_string(number) + ": " + problem);
  }
};

// `count` numbers after the keyword, each finite and within float range (OpenMesh stores
// floats and its `stream >> float` rejects what does not fit).
void check_numbers(const Line& line, std::string_view rest, int count, const char* what) {
  int seen = 0;
  for_each_token(rest, [&](std::string_view tok) {
    if (seen == count || tok.front() == '#') return false;
    double value = 0.0;
    switch (parse_number(tok, value)) {
      case NumberStatus::NotANumber:
        line.fail(std::string("cannot read ") + quote(tok) + " as a number in a " + what);
      case NumberStatus::NotFinite:
        line.fail("non-finite number " + quote(tok) + " in a " + what);
      case NumberStatus::Ok:
        break;
    }
    if (std::fabs(value) > FLT_MAX) {
      line.fail("number " + quote(tok) + " in a " + std::string(what) + " does not fit in a float");
    }
    ++seen;
    return true;
  });
  if (seen < count) {
    line.fail(std::string(what) + " needs " + std::to_string(count) + " numbers, found " +
              std::to_string(seen));
  }
}

// Largest positive 1-based index seen for one kind of element, checked against the final count
// at the end of the file (OpenMesh reads all vertices first, so forward references work).
struct ForwardRef {
  int64_t max_index = 0;
  std::size_t line = 0;
};

// Resolves one OBJ index (1-based, or negative = relative to the elements defined so far) to a
// 0-based index; `kind` names the element for messages.
int64_t resolve(const Line& line, std::string_view tok, std::size_t defined_so_far,
                ForwardRef& forward, const char* kind) {
  int64_t value = 0;
  if (!parse_integer(tok, value)) {
    line.fail(std::string("cannot read ") + quote(tok) + " as a " + kind + " index");
  }
  if (value == 0) line.fail(std::string(kind) + " index 0 (OBJ indices start at 1)");
  if (value < 0) {
    if (static_cast<uint64_t>(-(value + 1)) >= defined_so_far) {
      line.fail(std::string("relative ") + kind + " index " + std::to_string(value) +
                " points before the first " + kind + " (" + std::to_string(defined_so_far) +
                " defined so far)");
    }
    return static_cast<int64_t>(defined_so_far) + value;
  }
  if (value > forward.max_index) {
    forward.max_index = value;
    forward.line = line.number;
  }
  return value - 1;
}

}  // namespace

ObjScan scan_obj(const std::filesystem::path& path, std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark
  ObjScan scan;
  std::size_t normals = 0;
  ForwardRef forward_v, forward_vn;
  std::vector<int64_t> corners;

  std::size_t pos = 0;
  std::size_t number = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view content = text.substr(pos, end - pos);
    pos = end + 1;
    const Line line{path, ++number};

    std::string_view keyword;
    for_each_token(content, [&](std::string_view tok) {
      keyword = tok;
      return false;
    });
    if (keyword.empty() || keyword.front() == '#') continue;
    const std::string_view rest =
        content.substr(static_cast<std::size_t>(keyword.data() + keyword.size() - content.data()));

    if (keyword == "v") {
      check_numbers(line, rest, 3, "vertex");
      ++scan.positions;
    } else if (keyword == "vn") {
      check_numbers(line, rest, 3, "normal");
      ++normals;
    } else if (keyword == "vt") {
      // OpenMesh aborts the whole read on a `vt` line without two numbers.
      check_numbers(line, rest, 2, "texture coordinate");
    } else if (keyword == "f") {
      corners.clear();
      for_each_token(rest, [&](std::string_view tok) {
        if (tok.front() == '#') return false;  // trailing comment
        // v, v/vt, v//vn or v/vt/vn: the vertex index, and the normal index if present.
        const std::size_t slash1 = tok.find('/');
        corners.push_back(
            resolve(line, tok.substr(0, slash1), scan.positions, forward_v, "vertex"));
        if (slash1 != std::string_view::npos) {
          const std::size_t slash2 = tok.find('/', slash1 + 1);
          if (slash2 != std::string_view::npos && slash2 + 1 < tok.size()) {
            resolve(line, tok.substr(slash2 + 1), normals, forward_vn, "normal");
          }
        }
        return true;
      });
      if (corners.size() < 3) {
        line.fail("face has " + std::to_string(corners.size()) +
                  " vertices; a face needs at least 3");
      }
      // OpenMesh removes repeated vertices from a face and drops it if fewer than 3 remain.
      std::sort(corners.begin(), corners.end());
      const auto distinct = static_cast<std::size_t>(
          std::unique(corners.begin(), corners.end()) - corners.begin());
      if (distinct < 3) {
        ++scan.degenerate_faces;
      } else {
        scan.triangles += distinct - 2;
      }
    }
  }

  if (static_cast<uint64_t>(forward_v.max_index) > scan.positions) {
    fail(path, "line " + std::to_string(forward_v.line) + ": vertex index " +
                   std::to_string(forward_v.max_index) + " out of range (the file has " +
                   std::to_string(scan.positions) + " vertices)");
  }
  if (static_cast<uint64_t>(forward_vn.max_index) > normals) {
    fail(path, "line " + std::to_string(forward_vn.line) + ": normal index " +
                   std::to_string(forward_vn.max_index) + " out of range (the file has " +
                   std::to_string(normals) + " normals)");
  }
  return scan;
}

}  // namespace fastshade::io
