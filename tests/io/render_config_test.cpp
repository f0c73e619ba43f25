// Config files for `render --config`: every option survives a round trip, and a bad file is
// refused as strictly as a scene file, naming the file and the key.
#include "fastshade/render_config.h"

#include <gtest/gtest.h>

#include <string>

#include "fastshade/error.h"
#include "io/io_test_util.h"

namespace fastshade {
namespace {

RenderConfig parse(const std::string& text) { return parse_render_config(text, "tuned.json"); }

// The message of the InputError parsing `text` must throw.
std::string error_of(const std::string& text) {
  std::string message = "(accepted)";
  const auto parse_and_keep_message = [&] {
    try {
      parse(text);
    } catch (const InputError& e) {
      message = e.what();
      throw;
    }
  };
  EXPECT_THROW(parse_and_keep_message(), InputError) << text;
  return message;
}

std::vector<std::string_view> all_keys() {
  std::vector<std::string_view> keys;
  for (const RenderConfigKey& k : kRenderConfigKeys) keys.push_back(k.key);
  return keys;
}

TEST(RenderConfig, EveryOptionSurvivesARoundTrip) {
  RenderOptions o;
  o.threads = 3;
  o.tile_px = 16;
  o.method = ShadingMethod::Auto;
  o.srgb = true;
  o.isa = Isa::Scalar;
  o.brdf = {BrdfKind::Schlick};
  o.max_error = 2.5;
  o.spec_threshold = 1.0 / 255.0;  // not a short decimal: must come back bit for bit
  o.spec_method = SpecMethod::Phong;
  o.classifier = ClassifierRule::Paper;
  o.classify_min_px = 12.5;
  o.hidden_faces = HiddenFaces::Draw;
  const nlohmann::ordered_json provenance = {{"written_by", "test"}, {"table", {1, 2, 3}}};
  const RenderConfig back = parse(render_config_text(o, all_keys(), provenance));
  EXPECT_EQ(back.options, o) << back.options.to_string() << "\n" << o.to_string();
  EXPECT_EQ(back.keys, all_keys());

  // Keys left out keep their defaults and are not listed as set.
  const std::vector<std::string_view> some = {"method", "tile"};
  const RenderConfig partial = parse(render_config_text(o, some, nullptr));
  EXPECT_EQ(partial.keys, some);
  RenderOptions expected;
  expected.method = ShadingMethod::Auto;
  expected.tile_px = 16;
  EXPECT_EQ(partial.options, expected);
}

TEST(RenderConfig, LoadsAFileAndNamesAMissingOne) {
  testing::ScratchDir dir;
  const auto path = dir.write("c.json", R"({"options": {"method": "phong", "tile": 128}})");
  const RenderConfig c = load_render_config(path);
  EXPECT_EQ(c.options.method, ShadingMethod::Phong);
  EXPECT_EQ(c.options.tile_px, 128);
  const std::string missing = (dir.path() / "nope.json").string();
  try {
    load_render_config(missing);
    ADD_FAILURE() << "accepted a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": no such config file");
  }
}

TEST(RenderConfig, UnknownKeysAreRefusedByName) {
  EXPECT_EQ(error_of(R"({"options": {"tile": 32, "tiles": 64}})"),
            "tuned.json: options.tiles: unknown key (expected one of: method, tile, threads, isa, srgb, "
            "brdf, normals, gouraud, hidden_faces, max_error, spec_threshold, spec_method, classifier, "
            "classify_min_px)");
  EXPECT_EQ(error_of(R"({"options": {}, "comment": "x"})"),
            "tuned.json: comment: unknown key (expected one of: options, provenance)");
  EXPECT_EQ(error_of(R"({"provenance": {}})"),
            "tuned.json: options: missing (the render options, e.g. {\"method\": \"auto\", \"tile\": 32})");
  EXPECT_EQ(error_of(R"({"options": {}, "provenance": 3})"), "tuned.json: provenance: expected an object, got 3");
  EXPECT_EQ(error_of(R"({"options": {"tile": 32, "tile": 64}})"), "tuned.json: options.tile: duplicate key");
  EXPECT_EQ(error_of("[1]"), "tuned.json: expected an object, got an array of 1 element");
}

TEST(RenderConfig, BadValuesAreRefusedNamingTheKey) {
  EXPECT_EQ(error_of(R"({"options": {"tile": 48}})"),
            "tuned.json: options.tile: expected a power of two from 8 to 256, or 0 (sized from the image and threads), got 48");
  EXPECT_EQ(error_of(R"({"options": {"tile": "32"}})"),
            "tuned.json: options.tile: expected an integer in [-2147483648, 2147483647], got \"32\"");
  const auto starts_with = [](const std::string& text, const std::string& start) { return text.starts_with(start); };
  EXPECT_PRED2(starts_with, error_of(R"({"options": {"tile": 32.5}})"), "tuned.json: options.tile: expected an integer");
  EXPECT_EQ(error_of(R"({"options": {"srgb": 1}})"), "tuned.json: options.srgb: expected true or false, got 1");
  EXPECT_PRED2(starts_with, error_of(R"({"options": {"max_error": 300}})"),
               "tuned.json: options.max_error: expected 0 to 255");
  EXPECT_PRED2(starts_with, error_of(R"({"options": {"max_error": 1e300}})"),
               "tuned.json: options.max_error: expected a number");
  EXPECT_PRED2(starts_with, error_of(R"({"options": {"method": "nope"}})"),
               "tuned.json: options.method: unknown method 'nope'");
  EXPECT_EQ(error_of(R"({"options": {"method": "auto", "spec_method": "gouraud"}})"),
            "tuned.json: options.spec_method: unknown specular method 'gouraud' (expected hybrid or phong)");
  // A key for another method than the file's.
  EXPECT_EQ(error_of(R"({"options": {"method": "phong", "spec_threshold": 0.01}})"),
            "tuned.json: options.spec_threshold: applies to --method auto only");
  EXPECT_EQ(error_of(R"({"options": {"threads": -1}})"),
            "tuned.json: options.threads: expected 0 (all) to 1024, got -1");
}

}  // namespace
}  // namespace fastshade
