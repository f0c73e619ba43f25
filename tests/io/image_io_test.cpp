// write_image / read_image / check_output_path: round trips and failure behaviour.
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "fastshade/error.h"
#include "fastshade/image.h"

namespace fs = std::filesystem;
using fastshade::Image;
using fastshade::ImageF;
using fastshade::InputError;

namespace {

// A fresh empty directory per test, removed afterwards.
class ImageIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("fastshade_image_io_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::set<std::string> listing() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.insert(e.path().filename().string());
    return names;
  }

  fs::path dir_;
};

// Every 8-bit value appears, plus the extremes in each channel, on a non-square image.
Image test_image(int w = 19, int h = 14) {
  Image img;
  img.width = w;
  img.height = h;
  img.rgb.resize(size_t(w) * h * 3);
  for (size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = uint8_t((i * 37 + i / 3) % 256);
  img.rgb[0] = 0;
  img.rgb[1] = 255;
  img.rgb[2] = 128;
  return img;
}

// Message is one line and names the path.
void expect_message(const std::exception& e, const fs::path& path) {
  const std::string msg = e.what();
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_EQ(msg.rfind(path.string() + ": ", 0), 0u) << msg;
}

OIIO::TypeDesc stored_format(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return OIIO::TypeDesc::UNKNOWN;
  return in->spec().format;
}

void expect_exact_round_trip(const Image& img, const ImageF& back) {
  ASSERT_EQ(back.width, img.width);
  ASSERT_EQ(back.height, img.height);
  ASSERT_EQ(back.rgb.size(), img.rgb.size());
  for (size_t i = 0; i < img.rgb.size(); ++i) {
    ASSERT_NEAR(back.rgb[i], img.rgb[i] / 255.0f, 1e-7) << "at " << i;
    ASSERT_EQ(std::lround(back.rgb[i] * 255.0f), img.rgb[i]) << "at " << i;
  }
}

TEST_F(ImageIoTest, PngRoundTripIsExact) {
  const Image img = test_image();
  const fs::path p = dir_ / "out.png";
  fastshade::write_image(img, p);
  EXPECT_EQ(stored_format(p), OIIO::TypeDesc::UINT8);
  expect_exact_round_trip(img, fastshade::read_image(p));
}

TEST_F(ImageIoTest, TifRoundTripIsExact) {
  const Image img = test_image();
  const fs::path p = dir_ / "out.tif";
  fastshade::write_image(img, p);
  EXPECT_EQ(stored_format(p), OIIO::TypeDesc::UINT8);
  expect_exact_round_trip(img, fastshade::read_image(p));
}

TEST_F(ImageIoTest, ExrRoundTripWithinHalfAndBackToSameCode) {
  const Image img = test_image();
  const fs::path p = dir_ / "out.exr";
  fastshade::write_image(img, p);
  EXPECT_EQ(stored_format(p), OIIO::TypeDesc::HALF);
  const ImageF back = fastshade::read_image(p);
  ASSERT_EQ(back.width, img.width);
  ASSERT_EQ(back.height, img.height);
  for (size_t i = 0; i < img.rgb.size(); ++i) {
    const float exact = img.rgb[i] / 255.0f;
    // Half has an 11-bit significand: relative error at most 2^-11 after rounding.
    ASSERT_LE(std::fabs(back.rgb[i] - exact), exact * std::ldexp(1.0f, -11) + 1e-7f) << "at " << i;
    ASSERT_EQ(std::lround(back.rgb[i] * 255.0f), img.rgb[i]) << "at " << i;
  }
}

TEST_F(ImageIoTest, OverwritesExistingFileAndLeavesNoTemp) {
  const fs::path p = dir_ / "out.png";
  { std::ofstream(p) << "old contents"; }
  const Image img = test_image(4, 3);
  fastshade::write_image(img, p);
  expect_exact_round_trip(img, fastshade::read_image(p));
  EXPECT_EQ(listing(), std::set<std::string>{"out.png"});
}

TEST_F(ImageIoTest, SuccessfulWritesLeaveOnlyTargets) {
  const Image img = test_image(5, 5);
  fastshade::write_image(img, dir_ / "a.png");
  fastshade::write_image(img, dir_ / "b.exr");
  fastshade::write_image(img, dir_ / "c.tif");
  fastshade::write_image(img, dir_ / "a.png");  // again, over itself
  EXPECT_EQ(listing(), (std::set<std::string>{"a.png", "b.exr", "c.tif"}));
}

TEST_F(ImageIoTest, MissingDirectoryFailsBeforeWriting) {
  const fs::path missing = dir_ / "nope";
  const fs::path p = missing / "out.png";
  try {
    fastshade::check_output_path(p);
    FAIL() << "check_output_path accepted a missing directory";
  } catch (const InputError& e) {
    expect_message(e, p);
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  EXPECT_THROW(fastshade::write_image(test_image(), p), InputError);
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, UnsupportedExtensionFails) {
  const fs::path p = dir_ / "out.xyz";
  try {
    fastshade::check_output_path(p);
    FAIL() << "check_output_path accepted .xyz";
  } catch (const InputError& e) {
    expect_message(e, p);
    EXPECT_EQ(std::string(e.what()), p.string() + ": unsupported output format '.xyz'");
  }
  EXPECT_THROW(fastshade::write_image(test_image(), p), InputError);
  EXPECT_THROW(fastshade::check_output_path(dir_ / "noextension"), InputError);
  EXPECT_TRUE(listing().empty());
  EXPECT_FALSE(OIIO::has_error()) << "a pending OIIO error was left behind";
}

TEST_F(ImageIoTest, DirectoryAsOutputPathFails) {
  const fs::path p = dir_ / "looks_like.png";
  fs::create_directory(p);
  try {
    fastshade::check_output_path(p);
    FAIL() << "check_output_path accepted a directory";
  } catch (const InputError& e) {
    expect_message(e, p);
  }
  EXPECT_THROW(fastshade::write_image(test_image(), p), InputError);
  EXPECT_TRUE(fs::is_directory(p));
  EXPECT_TRUE(fs::is_empty(p));
  EXPECT_EQ(listing(), std::set<std::string>{"looks_like.png"});
}

TEST_F(ImageIoTest, ParentThatIsAFileFails) {
  const fs::path file = dir_ / "file";
  { std::ofstream(file) << "x"; }
  EXPECT_THROW(fastshade::check_output_path(file / "out.png"), InputError);
}

// The writer itself refuses (ICO holds at most 256x256) after the temp name was chosen: the
// error names the target and nothing is left in the directory.
TEST_F(ImageIoTest, WriterFailureLeavesNothing) {
  const fs::path p = dir_ / "big.ico";
  ASSERT_NO_THROW(fastshade::check_output_path(p));
  try {
    fastshade::write_image(test_image(300, 300), p);
    FAIL() << "ICO writer accepted 300x300";
  } catch (const InputError& e) {
    expect_message(e, p);
  }
  EXPECT_TRUE(listing().empty());
}

// libpng refuses rows wider than 1,000,000 px once the file is already open: the temp file
// exists on disk at that point and must be removed.
TEST_F(ImageIoTest, FailureAfterFileCreatedLeavesNothing) {
  const fs::path p = dir_ / "wide.png";
  try {
    fastshade::write_image(test_image(1000001, 1), p);
    FAIL() << "libpng accepted a 1000001 px row";
  } catch (const InputError& e) {
    expect_message(e, p);
  }
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, BadBufferFailsAndLeavesNothing) {
  Image img = test_image(4, 4);
  img.rgb.pop_back();
  EXPECT_THROW(fastshade::write_image(img, dir_ / "out.png"), InputError);
  EXPECT_THROW(fastshade::write_image(Image{}, dir_ / "out.png"), InputError);
  EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIoTest, ReadMissingFileFails) {
  const fs::path p = dir_ / "missing.png";
  try {
    fastshade::read_image(p);
    FAIL() << "read a missing file";
  } catch (const InputError& e) {
    expect_message(e, p);
  }
}

TEST_F(ImageIoTest, ReadGarbageFileFails) {
  for (const char* name : {"garbage.png", "garbage.exr", "garbage.txt", "empty.tif"}) {
    const fs::path p = dir_ / name;
    {
      std::ofstream f(p, std::ios::binary);
      if (std::string(name) != "empty.tif") f << "this is not an image\nsecond line\n";
    }
    try {
      fastshade::read_image(p);
      FAIL() << "read garbage " << name;
    } catch (const InputError& e) {
      expect_message(e, p);
    }
  }
  EXPECT_FALSE(OIIO::has_error()) << "a pending OIIO error was left behind";
}

TEST_F(ImageIoTest, ReadDirectoryFails) {
  EXPECT_THROW(fastshade::read_image(dir_), InputError);
}

// Writes an nch-channel 8-bit PNG straight through OIIO; channel c of pixel i is f(i, c).
void write_png_channels(const fs::path& p, int w, int h, int nch, int (*f)(int, int)) {
  std::vector<uint8_t> data(size_t(w) * h * nch);
  for (int i = 0; i < w * h; ++i)
    for (int c = 0; c < nch; ++c) data[size_t(i) * nch + c] = uint8_t(f(i, c));
  auto out = OIIO::ImageOutput::create(p.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(w, h, nch, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // store these bytes, do not un-premultiply
  ASSERT_TRUE(out->open(p.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, data.data()));
  ASSERT_TRUE(out->close());
}

TEST_F(ImageIoTest, GreyIsReplicated) {
  const fs::path p = dir_ / "grey.png";
  write_png_channels(p, 6, 2, 1, [](int i, int) { return i * 20; });
  const ImageF img = fastshade::read_image(p);
  ASSERT_EQ(img.width, 6);
  ASSERT_EQ(img.height, 2);
  for (int i = 0; i < 12; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(img.rgb[i * 3 + c], i * 20 / 255.0f);
}

TEST_F(ImageIoTest, GreyAlphaKeepsGrey) {
  const fs::path p = dir_ / "ga.png";
  write_png_channels(p, 3, 3, 2, [](int i, int c) { return c == 0 ? i * 25 : 255 - i; });
  const ImageF img = fastshade::read_image(p);
  for (int i = 0; i < 9; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(img.rgb[i * 3 + c], i * 25 / 255.0f);
}

// Alpha below 255 must not scale the colour (OIIO premultiplies PNG unless told not to).
TEST_F(ImageIoTest, RgbaDropsAlpha) {
  const fs::path p = dir_ / "rgba.png";
  write_png_channels(p, 4, 2, 4, [](int i, int c) { return c == 3 ? 100 + i : i * 30 + c; });
  const ImageF img = fastshade::read_image(p);
  ASSERT_EQ(img.rgb.size(), 4u * 2 * 3);
  for (int i = 0; i < 8; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(img.rgb[i * 3 + c], (i * 30 + c) / 255.0f);
}

}  // namespace

namespace {

fastshade::AovImages test_aovs(const Image& img) {
  fastshade::AovImages a;
  a.width = img.width;
  a.height = img.height;
  a.present = {true, true, true, true};
  const size_t n = size_t(img.width) * img.height;
  for (size_t i = 0; i < n; ++i) {
    const bool empty = i % 5 == 0;
    a.depth.push_back(empty ? 0.0f : 1.0f + 1e-3f * float(i) + 1e-7f);
    for (int c = 0; c < 3; ++c) a.normal.push_back(empty ? 0.0f : (c == 0 ? 0.6f : c == 1 ? -0.8f : 0.0f));
    a.triangle_id.push_back(empty ? -1 : int32_t(i * 7919));
    a.object_id.push_back(empty ? -1 : int32_t(i % 3));
  }
  return a;
}

// Channel `name` of an EXR as raw 32-bit words (float bits or uint), empty if absent.
std::vector<uint32_t> exr_channel(const fs::path& path, const std::string& name) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  const int c = spec.channelindex(name);
  if (c < 0) return {};
  const OIIO::TypeDesc type = spec.channelformat(c);
  std::vector<uint32_t> words(size_t(spec.width) * spec.height);
  if (!in->read_image(0, 0, c, c + 1, type, words.data())) return {};
  return words;
}

template <typename T>
std::vector<uint32_t> words_of(const std::vector<T>& v, int stride = 1, int offset = 0) {
  std::vector<uint32_t> out;
  for (size_t i = offset; i < v.size(); i += stride) {
    uint32_t w;
    std::memcpy(&w, &v[i], 4);
    out.push_back(w);
  }
  return out;
}

}  // namespace

// One EXR with colour and every AOV, each value exact: Z and N.* as FLOAT, ids as UINT with the
// int32 bits (-1 reads 0xFFFFFFFF).
TEST_F(ImageIoTest, AovsInAnExrAreNamedChannelsExactly) {
  const Image img = test_image();
  const fastshade::AovImages aovs = test_aovs(img);
  const fs::path p = dir_ / "out.exr";
  fastshade::write_image(img, aovs, p);
  EXPECT_EQ(listing(), std::set<std::string>{"out.exr"});
  auto in = OIIO::ImageInput::open(p.string());
  ASSERT_TRUE(in);
  const auto& names = in->spec().channelnames;
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()),
            (std::set<std::string>{"R", "G", "B", "Z", "N.X", "N.Y", "N.Z", "triangle_id", "object_id"}));
  EXPECT_EQ(in->spec().channelformat(in->spec().channelindex("triangle_id")), OIIO::TypeDesc::UINT32);
  EXPECT_EQ(exr_channel(p, "Z"), words_of(aovs.depth));
  EXPECT_EQ(exr_channel(p, "N.Y"), words_of(aovs.normal, 3, 1));
  EXPECT_EQ(exr_channel(p, "triangle_id"), words_of(aovs.triangle_id));
  EXPECT_EQ(exr_channel(p, "object_id"), words_of(aovs.object_id));
  EXPECT_EQ(exr_channel(p, "object_id")[0], 0xFFFFFFFFu);
  expect_exact_round_trip(img, fastshade::read_image(p));
}

// Another format: colour as asked, the AOVs (no colour) in STEM.aov.exr beside it.
TEST_F(ImageIoTest, AovsOfAPngGoBesideItAndAskedOnesOnly) {
  const Image img = test_image();
  fastshade::AovImages aovs = test_aovs(img);
  aovs.present = {.depth = true, .object_id = true};
  aovs.normal.clear();
  aovs.triangle_id.clear();
  const fs::path p = dir_ / "out.png";
  fastshade::write_image(img, aovs, p);
  EXPECT_EQ(listing(), (std::set<std::string>{"out.png", "out.aov.exr"}));
  EXPECT_EQ(fastshade::aov_path(p), dir_ / "out.aov.exr");
  auto in = OIIO::ImageInput::open((dir_ / "out.aov.exr").string());
  ASSERT_TRUE(in);
  const auto& names = in->spec().channelnames;
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()), (std::set<std::string>{"Z", "object_id"}));
  EXPECT_EQ(exr_channel(dir_ / "out.aov.exr", "Z"), words_of(aovs.depth));
  expect_exact_round_trip(img, fastshade::read_image(p));
}

// Buffers that do not match the image, or a colour write that fails once both files are
// open: an error naming the output, and neither file.
TEST_F(ImageIoTest, AovFailuresLeaveNeitherFile) {
  Image img = test_image();
  fastshade::AovImages aovs = test_aovs(img);
  aovs.depth.pop_back();
  EXPECT_THROW(fastshade::write_image(img, aovs, dir_ / "out.png"), InputError);
  const Image wide = test_image(1000001, 1);
  try {
    fastshade::write_image(wide, test_aovs(wide), dir_ / "wide.png");
    FAIL() << "libpng accepted a 1000001 px row";
  } catch (const InputError& e) {
    expect_message(e, dir_ / "wide.png");
  }
  EXPECT_TRUE(listing().empty());
}

// No time of writing in any format (OpenImageIO adds one to EXR and TIFF unless told): the
// same pixels make the same file, so batches on different engines and days compare by bytes.
TEST_F(ImageIoTest, FilesCarryNoTimeOfWriting) {
  const Image img = test_image();
  for (const char* name : {"a.exr", "a.tif", "a.png"}) {
    fastshade::write_image(img, test_aovs(img), dir_ / name);
    for (const fs::path& p : {dir_ / name, fastshade::aov_path(dir_ / name)}) {
      if (!fs::exists(p)) continue;
      std::ifstream in(p, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      EXPECT_FALSE(std::regex_search(bytes, std::regex("[0-9]{4}:[0-9]{2}:[0-9]{2} [0-9]{2}:[0-9]{2}"))) << p;
    }
  }
}
