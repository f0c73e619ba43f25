// Helpers for the io tests: a scratch directory, the shared models' expected counts.
#pragma once
#include <gtest/gtest.h>

#include <atomic>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

#include <unistd.h>

#include "support/shared_models.h"

namespace fastshade::testing {

// A fresh directory under the system temp dir, removed with its contents at the end.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "fastshade_io_" + std::to_string(::getpid()) + "_" +
                       std::to_string(counter++) + "_" + (info ? info->name() : "x");
    for (char& c : name) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
    }
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

  std::filesystem::path write(const std::string& name, std::string_view bytes) const {
    const auto p = path_ / name;
    std::ofstream out(p, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    EXPECT_TRUE(out.good()) << p;
    return p;
  }

 private:
  std::filesystem::path path_;
};

// Counts of every model in shared/models, as its README gives them for OpenMesh 9.0 (where
// OpenMesh differs from the table, the README's Notes give OpenMesh's number). -1: not checked.
// Boundary edges come from the Notes; 0 for a model the table marks closed and whose Notes
// report no OpenMesh duplication. cow.ply is closed in the table, but OpenMesh's 12 duplicated
// vertices open it (16 boundary edges measured), so it is left unchecked.
struct ModelCounts {
  const char* file;
  long faces;
  long vertices;
  bool normals;
  long boundary_edges;
  long unreferenced;
  long zero_area;
};

inline constexpr ModelCounts kModels[] = {
    // suzanne.obj: "duplicates 4 to 6 vertices" -> 511 (OBJ), 513 (PLY); 50 boundary edges.
    {"suzanne.obj", 968, 511, true, 50, -1, -1},
    {"suzanne.ply", 968, 513, true, -1, -1, -1},
    // cow.ply: "OpenMesh duplicates 12 non-manifold vertices on load (V=2,915)".
    {"cow.ply", 5804, 2915, false, -1, -1, -1},
    // spot.obj: "OpenMesh reads 2,930 V with 0 boundary edges".
    {"spot.obj", 5856, 2930, false, 0, -1, -1},
    {"teapot.obj", 6320, 3644, false, 1036, -1, -1},
    // teapot.stl: "OpenMesh merges them on read (3,250 V)".
    {"teapot.stl", 6320, 3250, false, -1, -1, -1},
    {"dragon_11k.ply", 11102, 7537, false, 2990, -1, -1},
    {"fandisk.off", 12946, 6475, false, 0, -1, -1},
    {"happy_buddha_54k.ply", 54384, 26986, true, 0, -1, 62},
    {"bunny.ply", 69451, 35947, false, 223, 1113, -1},
    {"horse.ply", 96966, 48485, true, 0, -1, -1},
    {"lucy_100k.ply", 99970, 49987, false, 0, -1, -1},
    {"armadillo_100k.ply", 99976, 49990, false, 0, -1, -1},
    {"dragon_871k.ply", 871306, 435545, false, 0, -1, 105118},
};

}  // namespace fastshade::testing
