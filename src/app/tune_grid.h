// The render configurations `fastshade tune` sweeps (method x tile, and for `auto` x threshold x
// specular kernel x classifier x dense-block bound), also the `auto` part of `render
// --max-error`'s calibration.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "app/commands.h"
#include "fastshade/render.h"

namespace fastshade {

// The default thresholds are these multiples of --max-error (8-bit steps): below the budget,
// at it, and above it (which the bound classifier may still keep within the budget where a
// scene's highlights are few; the table shows whether it did).
inline constexpr double kThresholdsPerBudget[] = {0.5, 1.0, 2.0};

struct Candidate {
  std::string label;  // as typed after `render --method`: "auto --tile 64 --spec-threshold ..."
  RenderOptions options;
};

// Appends to `out` the grid of `cmd` (its methods, tiles, thresholds, specular kernels and
// classifiers) over `base`, `render`'s defaults for this run (threads, ISA, --max-error...),
// without repeats, then `base` itself if the grid lacks it (the "x default" column's yardstick
// and the noise guard's baseline); returns base's index in `out`. Without cmd.thresholds, those
// of kThresholdsPerBudget at base.max_error. A value validate() refuses throws InputError naming
// the tune flag that lists it ("--tiles: ...").
std::size_t plan_candidates(const TuneCommand& cmd, const RenderOptions& base, std::vector<Candidate>& out);

}  // namespace fastshade
