#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/registry/param_spec.h"

namespace caustica {

class Properties;

// The path-length parameters that path, ptracer and bdpt share, read and
// checked in one place so the same values mean the same paths in each.
//   max_depth        longest path in segments from the camera; -1 for no limit,
//                    0 renders black, 1 shows emitters only, 2 direct light only
//   rr_depth         path vertices before Russian roulette may end a path
//   rr_max_survival  upper bound on the survival probability
//   rr_threshold     throughput below which roulette may end a camera path
//   hide_emitters    emitters seen directly by the camera appear black
struct PathSettings {
  int64_t max_depth = -1;
  int64_t rr_depth = 5;
  float rr_max_survival = 0.95f;
  float rr_threshold = 0.1f;
  bool hide_emitters = false;
};

PathSettings read_path_settings(const Properties& props);

// The declarations of those parameters, rr_depth's default given, followed
// by `more`.
std::vector<ParamSpec> path_settings_params(std::vector<ParamSpec> more = {}, int64_t rr_depth = 5);

}  // namespace caustica
