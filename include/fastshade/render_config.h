// Render options as a JSON file: `fastshade tune` writes one, `fastshade render --config` reads
// it. {"options": {"method": "auto", "tile": 32, ...}, "provenance": {...}}: each option key is
// a `render` flag without its dashes, '-' written '_'; "provenance" (optional) says where the
// options came from and is not read. Documented in docs/TUNING.md.
#pragma once
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "fastshade/options.h"

namespace fastshade {

struct RenderConfigKey {
  std::string_view key;   // in the file's "options"
  std::string_view flag;  // the `render` flag it stands for
  std::variant<int RenderOptions::*, double RenderOptions::*, bool RenderOptions::*, ShadingMethod RenderOptions::*,
               Isa RenderOptions::*, BrdfChoice RenderOptions::*, PhongNormals RenderOptions::*,
               GouraudMode RenderOptions::*, SpecMethod RenderOptions::*, ClassifierRule RenderOptions::*,
               HiddenFaces RenderOptions::*>
      member;
  bool classifying_only;  // applies to --method auto only, as validate() enforces
};

// Every option a config may set: all of RenderOptions.
inline constexpr RenderConfigKey kRenderConfigKeys[] = {
    {"method", "--method", &RenderOptions::method, false},
    {"tile", "--tile", &RenderOptions::tile_px, false},
    {"threads", "--threads", &RenderOptions::threads, false},
    {"isa", "--isa", &RenderOptions::isa, false},
    {"srgb", "--srgb", &RenderOptions::srgb, false},
    {"brdf", "--brdf", &RenderOptions::brdf, false},
    {"normals", "--normals", &RenderOptions::normals, false},
    {"gouraud", "--gouraud", &RenderOptions::gouraud, false},
    {"hidden_faces", "--hidden-faces", &RenderOptions::hidden_faces, false},
    {"max_error", "--max-error", &RenderOptions::max_error, false},
    {"spec_threshold", "--spec-threshold", &RenderOptions::spec_threshold, true},
    {"spec_method", "--spec-method", &RenderOptions::spec_method, true},
    {"classifier", "--classifier", &RenderOptions::classifier, true},
    {"classify_min_px", "--classify-min-px", &RenderOptions::classify_min_px, true},
};

// Sets `key`'s option of `to` to its value in `from`.
void copy_option(const RenderConfigKey& key, const RenderOptions& from, RenderOptions& to);

struct RenderConfig {
  RenderOptions options;               // the file's values; defaults for keys it has not
  std::vector<std::string_view> keys;  // the keys the file sets, in kRenderConfigKeys order
};

// Strict, as scene files: an unknown key, a value of the wrong type or one validate() refuses
// throws InputError "SOURCE: options.KEY: problem".
RenderConfig parse_render_config(const std::string& text, const std::string& source);
RenderConfig load_render_config(const std::filesystem::path& path);

// The file's text: `keys` of `options` (in kRenderConfigKeys order), then `provenance`.
std::string render_config_text(const RenderOptions& options, std::span<const std::string_view> keys,
                               const nlohmann::ordered_json& provenance);

}  // namespace fastshade
