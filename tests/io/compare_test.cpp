// compare_images / to_float on hand-made images with known answers.
#include "fastshade/compare.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "fastshade/error.h"

using fastshade::compare_images;
using fastshade::Image;
using fastshade::ImageF;
using fastshade::to_float;

namespace {

Image gradient(int w, int h) {
  Image img;
  img.width = w;
  img.height = h;
  img.rgb.resize(size_t(w) * h * 3);
  for (size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = uint8_t((i * 7) % 250 + 2);
  return img;
}

uint8_t& at(Image& img, int x, int y, int c) { return img.rgb[(size_t(y) * img.width + x) * 3 + c]; }

TEST(ToFloat, DividesBy255) {
  Image img;
  img.width = 2;
  img.height = 1;
  img.rgb = {0, 1, 51, 128, 254, 255};
  const ImageF f = to_float(img);
  ASSERT_EQ(f.width, 2);
  ASSERT_EQ(f.height, 1);
  ASSERT_EQ(f.rgb.size(), 6u);
  EXPECT_EQ(f.rgb[0], 0.0f);
  EXPECT_FLOAT_EQ(f.rgb[2], 0.2f);
  EXPECT_EQ(f.rgb[5], 1.0f);
}

TEST(Compare, IdenticalIsZeroAndInfinitePsnr) {
  const ImageF a = to_float(gradient(16, 9));
  const auto d = compare_images(a, a);
  EXPECT_EQ(d.max_abs_lsb, 0.0);
  EXPECT_EQ(d.rmse_lsb, 0.0);
  EXPECT_EQ(d.psnr_db, std::numeric_limits<double>::infinity());
  EXPECT_EQ(d.pct_over_1lsb, 0.0);
  EXPECT_EQ(d.worst_x, 0);
  EXPECT_EQ(d.worst_y, 0);
  EXPECT_EQ(d.nan_count, 0);
}

TEST(Compare, OnePixelOffBy3) {
  const int w = 10, h = 8;
  Image a = gradient(w, h), b = a;
  at(b, 7, 5, 1) += 3;
  const auto d = compare_images(to_float(a), to_float(b));
  EXPECT_NEAR(d.max_abs_lsb, 3.0, 1e-4);
  EXPECT_EQ(d.worst_x, 7);
  EXPECT_EQ(d.worst_y, 5);
  EXPECT_NEAR(d.pct_over_1lsb, 100.0 / (w * h), 1e-12);
  // By hand: one channel of 3 * 80 = 240 is off by 3, so rmse = sqrt(9 / 240).
  const double rmse = std::sqrt(9.0 / 240.0);
  EXPECT_NEAR(d.rmse_lsb, rmse, 1e-5);
  EXPECT_NEAR(d.psnr_db, 20.0 * std::log10(255.0 / rmse), 1e-4);
  EXPECT_EQ(d.nan_count, 0);
}

TEST(Compare, RmseByHandOnTinyImage) {
  // 2x1 image, differences (in LSB) 1, 2, 0 | 0, 0, 4: sum of squares 21 over 6 channels.
  Image a;
  a.width = 2;
  a.height = 1;
  a.rgb = {10, 20, 30, 40, 50, 60};
  Image b = a;
  b.rgb = {11, 18, 30, 40, 50, 64};
  const auto d = compare_images(to_float(a), to_float(b));
  EXPECT_NEAR(d.rmse_lsb, std::sqrt(21.0 / 6.0), 1e-5);
  EXPECT_NEAR(d.max_abs_lsb, 4.0, 1e-4);
  EXPECT_EQ(d.worst_x, 1);
  EXPECT_EQ(d.worst_y, 0);
  EXPECT_DOUBLE_EQ(d.pct_over_1lsb, 100.0);  // pixel 0 off by 2, pixel 1 off by 4
}

TEST(Compare, OneLsbIsNotOverOneLsb) {
  // Every code against its neighbour: all differences exactly 1 LSB after float noise.
  Image a;
  a.width = 255;
  a.height = 1;
  a.rgb.resize(255 * 3);
  for (int x = 0; x < 255; ++x)
    for (int c = 0; c < 3; ++c) a.rgb[x * 3 + c] = uint8_t(x);
  Image b = a;
  for (auto& v : b.rgb) ++v;
  const auto d = compare_images(to_float(a), to_float(b));
  EXPECT_EQ(d.pct_over_1lsb, 0.0);
  EXPECT_NEAR(d.max_abs_lsb, 1.0, 1e-4);
  EXPECT_NEAR(d.rmse_lsb, 1.0, 1e-4);
}

TEST(Compare, TiesGoToFirstPixelInScanOrder) {
  Image a = gradient(6, 4), b = a;
  at(b, 4, 1, 0) += 2;  // first in scan order (row 1)
  at(b, 1, 3, 2) += 2;  // same size, later row
  at(b, 5, 0, 1) += 1;  // smaller, earlier
  const auto d = compare_images(to_float(a), to_float(b));
  EXPECT_EQ(d.worst_x, 4);
  EXPECT_EQ(d.worst_y, 1);
  EXPECT_NEAR(d.pct_over_1lsb, 100.0 * 2 / 24, 1e-12);
}

TEST(Compare, SizeMismatchThrows) {
  const ImageF a = to_float(gradient(640, 480)), b = to_float(gradient(320, 240));
  try {
    compare_images(a, b);
    FAIL() << "sizes differ but no error";
  } catch (const fastshade::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("image sizes differ: 640x480 vs 320x240"),
              std::string::npos)
        << e.what();
  }
}

TEST(Compare, NanCountedAndExcluded) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Image base = gradient(4, 2);
  ImageF a = to_float(base), b = a;
  a.rgb[0] = nan;             // pixel (0,0), NaN in a
  b.rgb[5] = nan;             // pixel (1,0), NaN in b
  a.rgb[9] = b.rgb[9] = nan;  // pixel (3,0), NaN in both: one channel
  b.rgb[13] += 5.0f / 255.0f; // pixel (0,1), channel 1 off by 5
  const auto d = compare_images(a, b);
  EXPECT_EQ(d.nan_count, 3);
  EXPECT_NEAR(d.max_abs_lsb, 5.0, 1e-4);
  EXPECT_EQ(d.worst_x, 0);
  EXPECT_EQ(d.worst_y, 1);
  EXPECT_NEAR(d.rmse_lsb, std::sqrt(25.0 / (24 - 3)), 1e-4);  // NaN channels excluded
  EXPECT_TRUE(std::isfinite(d.psnr_db));
  EXPECT_NEAR(d.pct_over_1lsb, 100.0 / 8, 1e-12);
}

TEST(Compare, EqualInfinitiesAreNoDifference) {
  ImageF a = to_float(gradient(2, 2)), b = a;
  a.rgb[3] = b.rgb[3] = std::numeric_limits<float>::infinity();
  const auto d = compare_images(a, b);
  EXPECT_EQ(d.max_abs_lsb, 0.0);
  EXPECT_EQ(d.nan_count, 0);
}

}  // namespace
