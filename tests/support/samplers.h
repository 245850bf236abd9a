#pragma once

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <variant>

#include "core/sampling/sampler.h"

namespace caustica::test {

struct SamplerParameter {
  const char* name;
  std::variant<int64_t, bool> value;
};

// The sampler plugin `name` with the given integer and boolean parameters,
// the others at their defaults, created as a scene creates it.
std::unique_ptr<Sampler> make_sampler(const std::string& name, std::initializer_list<SamplerParameter> parameters = {});

}  // namespace caustica::test
