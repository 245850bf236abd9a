#pragma once

#include <string>
#include <vector>

#include "core/registry/param_spec.h"

namespace caustica {

// What every plugin of a category takes, read by the scene loader rather
// than by the plugin: a shape's interior and exterior media, a sensor's or
// an emitter's medium.
struct CategoryParams {
  std::string category;
  std::vector<ParamSpec> params;
  std::vector<std::string> child_categories;
};

const std::vector<CategoryParams>& category_params();

}  // namespace caustica
