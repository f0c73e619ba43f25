// The scene's "camera" key: explicit, fitted to the objects or calibrated (internal to io/).
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "fastshade/scene.h"
#include "io/json_path.h"

namespace fastshade {

// `camera` is the key's value or nullptr when the scene has none (a fit camera with defaults).
// The objects must be resolved already: a fit camera frames their transformed vertices.
Camera parse_camera(const json_path::Reader& reader, const nlohmann::json* camera,
                    const std::vector<Object>& objects);

// A camera built in code, checked as parse_camera checks one; throws InputError("camera.KEY").
void check_camera(const Camera& camera);

}  // namespace fastshade
