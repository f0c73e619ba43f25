// Stage times over many frames, reduced to the medians fastshade reports.
#pragma once
#include <span>

#include "fastshade/render.h"

namespace fastshade {

StageTimes median_stages(std::span<const StageTimes> frames);

}  // namespace fastshade
