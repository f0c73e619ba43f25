// The program as a test runs it: a fresh directory per test, the command's exit code and
// output, and the check every bad input must pass (exit 2, one line, nothing written).
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fastshade::test {

namespace fs = std::filesystem;

struct Outcome {
  int exit_code;  // -1 if the program did not exit normally (a signal)
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// A test of the program with a fresh scratch directory of its own (removed afterwards), where
// the program's output is captured and test files are written.
class CliFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("fastshade_cli_" + std::to_string(::getpid()) + "_" +
                                        test->test_suite_name() + "_" + test->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Outcome run(const std::string& args) {
    const std::string cmd = std::string(FASTSHADE_BINARY) + " " + args + " >" +
                            (dir_ / "stdout.txt").string() + " 2>" + (dir_ / "stderr.txt").string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "stdout.txt"),
            slurp(dir_ / "stderr.txt")};
  }
  // Writes `text` to dir_/name, creating the directories on the way.
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  // Exit 2, one line naming `needle`, and nothing left in the directory but our own files.
  void expect_bad_input(const std::string& args, const std::string& needle) {
    const auto before = listing();
    const Outcome r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "'" << needle << "' not in: " << r.err;
    EXPECT_EQ(listing(), before) << "output left behind by: " << args;
  }
  std::set<std::string> listing() {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) {
      const std::string n = e.path().filename().string();
      if (n != "stdout.txt" && n != "stderr.txt") names.insert(n);
    }
    return names;
  }
  // The largest channel error of `image` against the reference render of `scene` (a scene file,
  // then any flags such as --srgb), in whole 8-bit steps (compare's float path may add a few
  // 1e-6 LSB), both measured by the program.
  double max_error_against_reference(const std::string& scene, const fs::path& image) {
    const fs::path reference = dir_ / "reference.png";
    EXPECT_EQ(run("render " + scene + " -o " + reference.string() + " --method reference").exit_code, 0);
    const Outcome r = run("compare " + image.string() + " " + reference.string() + " --json");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    fs::remove(reference);
    return std::round(nlohmann::json::parse(r.out)["max_abs_lsb"].get<double>());
  }
  std::string scene_with(const std::string& objects, int width = 64) {
    return R"({"image": {"width": )" + std::to_string(width) +
           R"(, "height": 48, "background": [0, 0, 0]},
      "camera": {"fit": true, "distance": 3, "fovy_deg": 45},
      "lights": [{"type": "directional", "direction": [0, 0, 1], "color": [1, 1, 1]}],
      "materials": {"m": {"diffuse": 0.7, "specular": 0.3, "shininess": 20}},
      "objects": )" + objects + "}";
  }

  fs::path dir_;
};

}  // namespace fastshade::test
