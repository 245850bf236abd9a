#pragma once

#include <vector>

#include "core/image/render_merge.h"

namespace caustica {

// What `caustica merge` makes of its inputs, for the command line and
// Python alike: renders of one seed that all hold raw sums are disjoint
// ranges of the same samples and merge exactly (merge_sample_ranges);
// otherwise they are independent estimates, merged by sample count
// (merge_renders) after their raw sums are dropped. The merged render
// records its estimated error (caustica:estimated_mse and
// caustica:estimated_rel_mse) where its variance is known, so that
// comparisons against it as a reference can discount it. Throws
// std::invalid_argument naming the part that does not fit. Parts may hold
// the same channels in different orders; the merge keeps the first's.
RenderFile merge_parts(std::vector<RenderFile> parts);

}  // namespace caustica
