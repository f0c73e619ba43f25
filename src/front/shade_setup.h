// The frame's shading constants (frame/shade_constants.h), built in one place from the scene,
// the view and the user's choices: lights to view space, materials with their fitted lobes,
// and the error budgets the kernels read.
#pragma once
#include "fastshade/scene.h"
#include "fastshade/options.h"
#include "frame/shade_constants.h"
#include "front/vertex_stage.h"

namespace fastshade {

ShadeConstants shade_constants(const Scene& scene, const ViewTransform& xf, const RenderOptions& options = {});

}  // namespace fastshade
