#include "core/render/path_settings.h"

#include <string>

#include "core/registry/properties.h"

namespace caustica {

PathSettings read_path_settings(const Properties& props) {
  PathSettings s;
  s.max_depth = props.get_int("max_depth");
  s.rr_depth = props.get_int("rr_depth");
  s.rr_max_survival = props.get_float("rr_max_survival");
  s.rr_threshold = props.get_float("rr_threshold");
  s.hide_emitters = props.get_bool("hide_emitters");
  if (s.max_depth < -1) throw props.error("max_depth", "must be -1 (unlimited) or at least 0");
  if (s.rr_depth < 1) throw props.error("rr_depth", "must be at least 1");
  if (!(s.rr_max_survival > 0 && s.rr_max_survival <= 1)) throw props.error("rr_max_survival", "must be in (0, 1]");
  if (!(s.rr_threshold > 0))
    throw props.error("rr_threshold", "must be positive (1e30 for roulette at any throughput)");
  return s;
}

std::vector<ParamSpec> path_settings_params(std::vector<ParamSpec> more, int64_t rr_depth) {
  std::vector<ParamSpec> params{
      {"max_depth", ParamType::Integer, "-1",
       "longest path in segments; -1 for as long as roulette allows, up to 4096; 0 renders black, 1 emitters only, 2 "
       "direct light only"},
      {"rr_depth", ParamType::Integer, std::to_string(rr_depth),
       "path vertices before Russian roulette may end a path"},
      {"rr_max_survival", ParamType::Float, "0.95", "upper bound on the survival probability, in (0, 1]"},
      {"rr_threshold", ParamType::Float, "0.1",
       "camera paths meet Russian roulette only once their throughput falls below this; 1e30 for any throughput"},
      {"hide_emitters", ParamType::Boolean, "false", "emitters seen directly by the camera appear black"}};
  params.insert(params.end(), more.begin(), more.end());
  return params;
}

}  // namespace caustica
