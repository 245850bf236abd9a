#include "tests/support/samplers.h"

#include "core/registry/properties.h"

namespace caustica::test {

std::unique_ptr<Sampler> make_sampler(const std::string& name, std::initializer_list<SamplerParameter> parameters) {
  const PluginInfo* info = Registry::instance().find("sampler", name);
  Properties props(*info, {"test", 1});
  for (const auto& [parameter, value] : parameters) {
    if (const int64_t* n = std::get_if<int64_t>(&value))
      props.set(parameter, {ValueKind::Integer, *n, {"test", 1}});
    else
      props.set(parameter, {ValueKind::Boolean, std::get<bool>(value), {"test", 1}});
  }
  return std::dynamic_pointer_cast<Sampler>(info->create(props))->clone();
}

}  // namespace caustica::test
