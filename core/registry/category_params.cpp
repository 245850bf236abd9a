#include "core/registry/category_params.h"

namespace caustica {

const std::vector<CategoryParams>& category_params() {
  static const std::vector<CategoryParams> params = {
      {"shape",
       {{"interior", ParamType::Medium, std::nullopt, "the medium inside the shape (it then bounds media)"},
        {"exterior", ParamType::Medium, std::nullopt, "the medium outside the shape (it then bounds media)"}},
       {}},
      // As in Mitsuba, a sensor's or an emitter's medium is any nested
      // <medium>, named or not.
      {"sensor", {}, {"medium"}},
      {"emitter", {}, {"medium"}},
  };
  return params;
}

}  // namespace caustica
