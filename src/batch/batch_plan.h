// A batch's plan and template from its spec (include/fastshade/batch.h): the part the command
// line's workers and fastshade.batch share before any image is rendered.
#pragma once
#include "fastshade/batch.h"
#include "io/scene_template.h"

namespace fastshade {

// The spec's template (the embedded default if none), with its image size.
SceneTemplate batch_template(const BatchSpec& spec);

struct PreparedBatch {
  SceneTemplate scene;
  BatchPlan plan;
};
// plan_batch() and the template it read.
PreparedBatch prepare_batch(const BatchSpec& spec);

}  // namespace fastshade
