#pragma once

#include <vector>

#include "core/image/render_merge.h"

namespace caustica {

// Whether a render holds the film's raw sums (render --raw-sums).
bool has_raw_sums(const RenderFile& render);

// Whether the render may go to a half-float EXR: not when it holds raw sums
// (they must stay exact), nor values beyond half's range (they would
// become infinities).
bool half_float_suits(const RenderFile& render);

// The render without its raw sums, for merges that cannot use them.
RenderFile without_raw_sums(RenderFile render);

// Merges renders of one scene, integrator and seed over disjoint ranges of
// sample indices (render --first-sample N --spp COUNT --raw-sums) into the
// render of their union: the raw sums are added and resolved as the film
// resolves them; the film's sums are exact (ExactSum), so the image is that
// of one render of all the samples, bit for bit. The metadata lists the ranges in caustica:ranges
// (adjacent ones joined), so merges merge again. Throws
// std::invalid_argument naming the file when a part lacks raw sums,
// differs in size, channels, scene, integrator or seed, or overlaps another
// part's range.
RenderFile merge_sample_ranges(const std::vector<RenderFile>& parts);

}  // namespace caustica
