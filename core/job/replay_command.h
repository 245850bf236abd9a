#pragma once

#include <string>
#include <vector>

#include "core/film/film_buffer.h"
#include "core/job/render_job.h"

namespace caustica {

// The command line that replays sample `id` of a render of `scene` with the
// scene parameters `defines` (name=value, as given to -D) and `settings`:
// every option that decides what the sample draws and computes (the
// parameters, the integrator, the sample count the sampler stratifies,
// the seed, the transport), each argument quoted for a POSIX shell where
// it needs it. Without them a replay would take another film size,
// integrator or sampler, and another sample.
std::string replay_command(const std::string& scene, const std::vector<std::string>& defines,
                           const RenderSettings& settings, SampleId id);

}  // namespace caustica
