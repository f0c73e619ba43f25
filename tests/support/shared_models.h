// Where the tests find the shared models (../shared/models beside the clone, as CI lays it
// out; FASTSHADE_SHARED_MODELS=DIR points elsewhere). A test that needs one skips with a line
// saying what is missing and where it goes; a model that is there but wrong fails (the counts
// in tests/io/io_test_util.h).
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace fastshade::testing {

inline std::filesystem::path shared_models() {
  if (const char* dir = std::getenv("FASTSHADE_SHARED_MODELS"); dir != nullptr && *dir != '\0') return dir;
  return FASTSHADE_SHARED_MODELS;
}

inline constexpr const char* kSharedModelsHint =
    "(the shared models: clone with shared/ beside the checkout, or set FASTSHADE_SHARED_MODELS=DIR)";

}  // namespace fastshade::testing

// Skips the test unless the shared model folder exists.
#define FASTSHADE_REQUIRE_SHARED_MODELS()                                                       \
  do {                                                                                          \
    if (!std::filesystem::is_directory(::fastshade::testing::shared_models())) {                \
      GTEST_SKIP() << "needs " << ::fastshade::testing::shared_models().string() << " "        \
                   << ::fastshade::testing::kSharedModelsHint;                                  \
    }                                                                                           \
  } while (0)

// Skips the test unless shared model FILE exists.
#define FASTSHADE_REQUIRE_SHARED_MODEL(file)                                                    \
  do {                                                                                          \
    if (!std::filesystem::is_regular_file(::fastshade::testing::shared_models() / (file))) {    \
      GTEST_SKIP() << "needs " << (::fastshade::testing::shared_models() / (file)).string()     \
                   << " " << ::fastshade::testing::kSharedModelsHint;                           \
    }                                                                                           \
  } while (0)
