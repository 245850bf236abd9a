#pragma once

#include <string>
#include <vector>

#include "core/registry/param_spec.h"

namespace caustica {

// Parameters Mitsuba 3 gives every plugin of a category that cannot change
// what caustica renders (differentiable rendering's weights, how samples
// are split into passes). Every plugin of
// the category accepts them; a scene that gives one gets a line saying it
// is ignored and why.
struct IgnoredParam {
  std::string category;
  ParamSpec spec;  // no default: recorded only where given
  std::string why;
};

const std::vector<IgnoredParam>& ignored_params();

// The ignored parameter `name` of `category`, if there is one.
const IgnoredParam* find_ignored_param(const std::string& category, const std::string& name);

}  // namespace caustica
