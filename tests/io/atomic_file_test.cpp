// Temporary files: a TempFile's name leads back to its target, and nothing else does.
#include "fastshade/atomic_file.h"

#include <gtest/gtest.h>

#include "io/io_test_util.h"

namespace fastshade {
namespace {

TEST(AtomicFile, TempFileNamesLeadBackToTheirTarget) {
  const testing::ScratchDir scratch;
  for (const char* target : {"a.png", "x-v01.exr", "no_extension", ".hidden.tif", "a.tmp1.2.png"}) {
    const TempFile temp(scratch.path() / target);
    EXPECT_EQ(temp_file_target(temp.path().filename().string()), target) << temp.path();
  }
  for (const char* other : {"a.png", ".a.png", ".a.png.tmp", ".a.png.tmp12.png", ".a.png.tmp1.2.exr",
                            ".a.png.tmpx.2.png", ".a.png.tmp1.2x.png", ".tmp1.2", ""})
    EXPECT_EQ(temp_file_target(other), "") << other;
}

}  // namespace
}  // namespace fastshade
