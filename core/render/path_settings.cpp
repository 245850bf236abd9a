#include "core/render/path_settings.h"

#include "core/registry/properties.h"

namespace caustica {

PathSettings read_path_settings(const Properties& props) {
  PathSettings s;
  s.max_depth = props.get_int("max_depth");
  s.rr_depth = props.get_int("rr_depth");
  s.rr_max_survival = props.get_float("rr_max_survival");
  s.hide_emitters = props.get_bool("hide_emitters");
  if (s.max_depth < -1) throw props.error("max_depth", "must be -1 (unlimited) or at least 0");
  if (s.rr_depth < 1) throw props.error("rr_depth", "must be at least 1");
  if (!(s.rr_max_survival > 0 && s.rr_max_survival <= 1)) throw props.error("rr_max_survival", "must be in (0, 1]");
  return s;
}

std::vector<ParamSpec> path_settings_params(std::vector<ParamSpec> more) {
  std::vector<ParamSpec> params{{"max_depth", ParamType::Integer, "-1", "longest path, -1 for unlimited"},
                                {"rr_depth", ParamType::Integer, "5", "depth where Russian roulette starts"},
                                {"rr_max_survival", ParamType::Float, "0.95", "bound on the survival probability"},
                                {"hide_emitters", ParamType::Boolean, "false", "hide directly visible emitters"}};
  params.insert(params.end(), more.begin(), more.end());
  return params;
}

std::string describe(const std::string& integrator, const PathSettings& s) {
  return integrator + " max_depth=" + std::to_string(s.max_depth) + " rr_depth=" + std::to_string(s.rr_depth) +
         " rr_max_survival=" + std::to_string(s.rr_max_survival) +
         " hide_emitters=" + (s.hide_emitters ? "true" : "false");
}

}  // namespace caustica
