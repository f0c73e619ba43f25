// Every seed of fuzz/corpus and every input a fuzzer once found (fuzz/regressions), replayed
// through the fuzz harness: each must be accepted or rejected with the one-line InputError
// (fuzz/fuzz_inputs.h). The sanitized build runs the same test (docs/FUZZING.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_inputs.h"

namespace fastshade {
namespace {

const std::filesystem::path kFuzzDir = FASTSHADE_FUZZ_DIR;

std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file()) files.push_back(entry.path());
  return files;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class FuzzInputs : public ::testing::TestWithParam<std::string_view> {};

TEST_P(FuzzInputs, SeedsAndFoundInputsAreAcceptedOrRejectedInOneLine) {
  const std::string target(GetParam());
  const auto seeds = files_in(kFuzzDir / "corpus" / target);
  EXPECT_FALSE(seeds.empty()) << "no seeds in " << (kFuzzDir / "corpus" / target);
  auto inputs = seeds;
  for (const auto& found : files_in(kFuzzDir / "regressions" / target)) inputs.push_back(found);
  for (const auto& path : inputs) {
    const std::string bytes = read_bytes(path);
    const auto finding =
        fuzz::run_target(target, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    EXPECT_FALSE(finding.has_value()) << path << ": " << finding.value_or("");
  }
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, FuzzInputs, ::testing::ValuesIn(fuzz::kTargets),
                         [](const auto& info) { return std::string(info.param); });

TEST(FuzzHarness, RejectsAnUnknownTargetAndReportsNonInputErrors) {
  const uint8_t byte = 0;
  EXPECT_TRUE(fuzz::run_target("no_such_target", &byte, 1).has_value());
  // A lying PLY header: the rejection must be InputError naming the file, not bad_alloc.
  const std::string lying = "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 1\n"
                            "property list uchar int vertex_indices\nend_header\n";
  EXPECT_FALSE(fuzz::run_target("mesh_ply", reinterpret_cast<const uint8_t*>(lying.data()), lying.size()));
  const std::string empty_scene = "{}";
  EXPECT_FALSE(fuzz::run_target("scene_json", reinterpret_cast<const uint8_t*>(empty_scene.data()), 2));
}

}  // namespace
}  // namespace fastshade
