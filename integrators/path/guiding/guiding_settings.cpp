#include "integrators/path/guiding/guiding_settings.h"

#include "core/bsdf/bsdf.h"
#include "core/registry/properties.h"
#include "core/scene/scene.h"

namespace caustica {

GuidingSettings read_guiding_settings(const Properties& props) {
  GuidingSettings s;
  const int64_t passes = props.get_int("training_passes");
  if (passes < 1 || passes > 20)
    throw props.error("training_passes",
                      "must be between 1 and 20 (pass 0 learns unguided; each later training pass of twice the "
                      "samples learns from the one before)");
  s.training_passes = int(passes);
  s.bsdf_fraction = props.get_float("bsdf_fraction");
  if (!(s.bsdf_fraction > 0 && s.bsdf_fraction <= 1))
    throw props.error("bsdf_fraction",
                      "must be in (0, 1]: with 0, directions the learned distribution gives no density would never "
                      "be sampled, and the image would lose their light");
  s.refinement.spatial_threshold = props.get_float("spatial_threshold");
  if (!(s.refinement.spatial_threshold > 0)) throw props.error("spatial_threshold", "must be positive");
  s.refinement.directional_threshold = props.get_float("directional_threshold");
  if (!(s.refinement.directional_threshold > 0 && s.refinement.directional_threshold < 1))
    throw props.error("directional_threshold", "must be in (0, 1)");
  const int64_t min_records = props.get_int("min_records");
  if (min_records < 0 || min_records > 1000000000)
    throw props.error("min_records", "must be between 0 and 1000000000 (records a guide needs before it guides)");
  s.refinement.min_records = uint64_t(min_records);
  const int64_t mib = props.get_int("max_tree_memory");
  if (mib < 1 || mib > (int64_t(1) << 20)) throw props.error("max_tree_memory", "must be between 1 and 1048576 (MiB)");
  s.refinement.max_bytes = size_t(mib) << 20;
  s.light_paths = props.get_float("light_paths");
  if (!(s.light_paths >= 0 && s.light_paths <= 1024))
    throw props.error("light_paths",
                      "must be between 0 and 1024 (light paths per camera sample of a training pass; 0 learns "
                      "from the camera paths alone)");
  s.always_guide = props.get_bool("always_guide");
  s.adjoint_roulette = props.get_float("adjoint_roulette");
  if (!(s.adjoint_roulette >= 0 && s.adjoint_roulette <= 1))
    throw props.error("adjoint_roulette",
                      "must be in [0, 1]: the share of its first vertex's expected contribution below which a path "
                      "meets roulette (0 leaves roulette to path's rule)");
  s.skip_unseen_lights = props.get_bool("skip_unseen_lights");
  return s;
}

std::vector<ParamSpec> guiding_params() {
  return {{"training_passes", ParamType::Integer, "6",
           "passes of 1, 2, 4, ... samples per pixel that learn where light comes from (1 to 20); later passes "
           "sample by the last distribution learnt"},
          {"bsdf_fraction", ParamType::Float, "0.5",
           "probability of sampling the BSDF rather than the learned distribution, in (0, 1]"},
          {"spatial_threshold", ParamType::Float, "4000",
           "records a region may hold, times sqrt(samples per pixel of the pass), before it is halved"},
          {"directional_threshold", ParamType::Float, "0.01",
           "share of a region's energy above which a directional quadrant is divided, in (0, 1)"},
          {"min_records", ParamType::Integer, "128",
           "records a region's guide must learn from before its paths are guided; below it they sample the BSDF "
           "alone"},
          {"max_tree_memory", ParamType::Integer, "256", "MiB the guiding trees may take; refinement stops there"},
          {"light_paths", ParamType::Float, "1",
           "light paths traced per camera sample of a training pass, whose records teach the directions (0 to "
           "1024); 0 learns them from the camera paths' records, as Müller et al. 2017"},
          {"always_guide", ParamType::Boolean, "false",
           "guide every pass; by default a training pass whose guided samples cost more (relative variance x "
           "vertices) than pass 0's unguided ones ends guiding, and later samples are unguided"},
          {"adjoint_roulette", ParamType::Float, "0.5",
           "after the training, roulette by expected contribution (Vorba and Krivanek 2016, without splitting): "
           "a path whose weight times its region's learnt radiance falls below this share of its first "
           "vertex's survives with the ratio; in [0, 1], 0 keeps path's roulette alone"},
          {"skip_unseen_lights", ParamType::Boolean, "true",
           "guided vertices take no light sample where their guide's light samples reached no light over a "
           "training pass (at least 256 of them); emission their directions find there then counts in full"}};
}

std::string guiding_pointless(const Scene& scene, int64_t max_depth) {
  if ((scene.features().lobes & (kDiffuse | kGlossy)) == 0)
    return "every surface scatters through delta lobes only (mirrors, smooth glass), which guiding leaves alone";
  if (max_depth >= 0 && max_depth <= 2)
    return "max_depth " + std::to_string(max_depth) + " leaves no light after a bounce";
  return "";
}

}  // namespace caustica
