// A batch's template from its spec (include/fastshade/batch.h): what planning and every engine
// that renders a plan read.
#pragma once
#include "fastshade/batch.h"
#include "io/scene_template.h"

namespace fastshade {

// The spec's template (the embedded default if none), with its image size.
SceneTemplate batch_template(const BatchSpec& spec);

}  // namespace fastshade
