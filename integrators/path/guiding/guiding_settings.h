#pragma once

#include <string>
#include <vector>

#include "core/registry/param_spec.h"
#include "integrators/path/guiding/spatial_tree.h"

namespace caustica {

class Properties;
class Scene;

// guided_path's own parameters (beside path's):
//   training_passes        passes of 1, 2, 4, ... samples per pixel that learn; every later
//                          pass samples by what the last of them learnt
//   bsdf_fraction          probability of sampling the BSDF instead of the learned distribution
//   spatial_threshold      records a region holds, times sqrt(samples per pixel of the pass), before it is halved
//   directional_threshold  share of a region's energy above which a directional quadrant is divided
//   min_records            records a guide needs before its paths are guided
//   max_tree_memory        MiB the trees may take; refinement stops there
//   light_paths            light paths traced per camera sample of a training pass, whose
//                          records teach the directions; 0: camera paths' records teach them
//   always_guide           keep guiding where the training passes judge it costs more than it saves
//   adjoint_roulette       after the training, a path whose expected contribution (its weight times
//                          the radiance its region was learnt to send) falls below this share of its
//                          first vertex's meets roulette by it; 0: path's roulette alone
//   skip_unseen_lights     no light sample at guided vertices of guides whose light samples
//                          reached no light over a whole pass
struct GuidingSettings {
  int training_passes = 6;
  float bsdf_fraction = 0.5f;
  double light_paths = 1;
  bool always_guide = false;
  float adjoint_roulette = 0.5f;
  bool skip_unseen_lights = true;
  GuidingRefinement refinement;
};

GuidingSettings read_guiding_settings(const Properties& props);
std::vector<ParamSpec> guiding_params();

// Why guiding cannot help this scene at the given path length limit, or
// empty if it can: no vertex to guide (every surface a delta lobe), or no
// light that arrives after a bounce (paths of two segments at most).
std::string guiding_pointless(const Scene& scene, int64_t max_depth);

}  // namespace caustica
