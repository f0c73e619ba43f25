#include "batch/batch_inputs.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <system_error>

#include "fastshade/error.h"

namespace fastshade {
namespace fs = std::filesystem;

namespace {

// Output names keep at most this many characters of the mesh's stem: with the hash, the view
// and the extension a name stays far below the usual 255-byte file-name limit.
constexpr std::size_t kMaxStemChars = 100;

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool is_mesh_file_name(const fs::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl";
}

bool is_list_file_name(const fs::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".txt" || ext == ".lst" || ext == ".list";
}

void walk_directory(const fs::path& dir, std::vector<fs::path>& found) {
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    std::error_code file_ec;
    if (is_mesh_file_name(it->path()) && it->is_regular_file(file_ec)) found.push_back(it->path());
  }
  if (ec) throw InputError(dir.string(), "cannot read the directory: " + ec.message());
}

// A list file's line, or a path below a directory: a directory is walked, anything else is a
// mesh file whose load will say what is wrong with it.
void add_path(const fs::path& path, std::vector<fs::path>& found) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    walk_directory(path, found);
  } else {
    found.push_back(path);
  }
}

std::string trim(const std::string& line) {
  const auto space = [](unsigned char c) { return std::isspace(c) != 0; };
  const auto first = std::find_if_not(line.begin(), line.end(), space);
  const auto last = std::find_if_not(line.rbegin(), line.rend(), space).base();
  return first < last ? std::string(first, last) : std::string();
}

void read_list_file(const fs::path& list, std::vector<fs::path>& found) {
  std::error_code ec;
  if (!fs::is_regular_file(list, ec))
    throw InputError(list.string(), fs::exists(list, ec) ? "not a regular file" : "no such list file");
  std::ifstream in(list, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) throw InputError(list.string(), "cannot read the list file");
  const std::string bytes = text.str();
  if (bytes.find('\0') != std::string::npos)
    throw InputError(list.string(), "not a text file (NUL bytes): expected one mesh path a line");
  const fs::path base = list.parent_path();
  std::istringstream lines(bytes);
  for (std::string line; std::getline(lines, line);) {
    const std::string entry = trim(line);
    if (entry.empty() || entry[0] == '#') continue;
    const fs::path path(entry);
    add_path(path.is_absolute() ? path : base / path, found);
  }
}

std::string safe_stem(const fs::path& path) {
  std::string stem = path.stem().string().substr(0, kMaxStemChars);
  for (char& c : stem) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) c = '_';
  }
  return stem;
}

}  // namespace

std::string stable_hash(std::string_view text) {
  uint64_t hash = 14695981039346656037ull;  // FNV-1a 64 offset basis
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;  // FNV-1a 64 prime
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

std::vector<BatchMesh> find_meshes(const std::vector<std::string>& inputs) {
  std::vector<fs::path> found;
  for (const std::string& input : inputs) {
    const fs::path path(input);
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      walk_directory(path, found);
    } else if (is_list_file_name(path)) {
      read_list_file(path, found);
    } else if (is_mesh_file_name(path)) {
      found.push_back(path);  // may not exist: reported as a failed mesh
    } else {
      throw InputError(input, fs::exists(path, ec)
                                  ? "not a mesh file (.obj, .off, .ply, .stl), a directory or a "
                                    "list file (.txt, .lst, .list)"
                                  : "no such file or directory");
    }
  }

  std::vector<BatchMesh> meshes;
  for (const fs::path& path : found) {
    BatchMesh mesh;
    mesh.path = path.lexically_normal();
    mesh.key = mesh.path.generic_string();
    meshes.push_back(std::move(mesh));
  }
  std::sort(meshes.begin(), meshes.end(),
            [](const BatchMesh& a, const BatchMesh& b) { return a.key < b.key; });

  std::vector<BatchMesh> unique;
  std::set<fs::path> seen;  // canonical paths: one file reached twice is rendered once
  std::map<std::string, std::string> names;  // name -> key
  for (BatchMesh& mesh : meshes) {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(mesh.path, ec);
    if (ec) canonical = fs::absolute(mesh.path, ec);
    if (!seen.insert(canonical).second) continue;
    mesh.name = safe_stem(mesh.path) + "-" + stable_hash(mesh.key);
    if (auto [it, fresh] = names.emplace(mesh.name, mesh.key); !fresh)
      throw InputError(mesh.key, "gets the same output name as " + it->second + " (" + mesh.name + ")");
    const std::uintmax_t bytes = fs::file_size(mesh.path, ec);
    mesh.file_bytes = ec ? 0 : bytes;
    unique.push_back(std::move(mesh));
  }
  if (unique.empty()) {
    std::string where;
    for (const std::string& input : inputs) where += (where.empty() ? "" : " ") + input;
    throw InputError(where.empty() ? "batch" : where, "no mesh files (.obj, .off, .ply, .stl) found");
  }
  return unique;
}

namespace {

InputError bad_shard(const std::string& text, const std::string& where) {
  return InputError(where, "expected I/N with 0 <= I < N <= " + std::to_string(kMaxShards) +
                               " (I counts from 0), got '" + text + "'");
}

bool valid_shard(Shard shard) {
  return shard.count >= 1 && shard.count <= kMaxShards && shard.index >= 0 && shard.index < shard.count;
}

}  // namespace

void check_shard(Shard shard, const std::string& where) {
  if (!valid_shard(shard)) throw bad_shard(std::to_string(shard.index) + "/" + std::to_string(shard.count), where);
}

Shard parse_shard(const std::string& text, const std::string& where) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) throw bad_shard(text, where);
  Shard shard;
  const char* begin = text.data();
  const char* end = begin + text.size();
  auto [index_end, index_err] = std::from_chars(begin, begin + slash, shard.index);
  auto [count_end, count_err] = std::from_chars(begin + slash + 1, end, shard.count);
  if (index_err != std::errc() || index_end != begin + slash || count_err != std::errc() || count_end != end ||
      !valid_shard(shard))
    throw bad_shard(text, where);
  return shard;
}

std::vector<BatchMesh> take_shard(const std::vector<BatchMesh>& meshes, Shard shard) {
  std::vector<BatchMesh> part;
  for (std::size_t j = static_cast<std::size_t>(shard.index); j < meshes.size();
       j += static_cast<std::size_t>(shard.count))
    part.push_back(meshes[j]);
  return part;
}

}  // namespace fastshade
