#include "core/registry/parameter_tables.h"

#include <algorithm>

#include "core/registry/registry.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// The scene file's elements in the order a scene usually names them.
const char* const kCategories[] = {"integrator", "sensor", "film",    "rfilter", "sampler",
                                   "shape",      "bsdf",   "texture", "emitter", "tonemap"};

std::string cell(std::string text) {
  for (size_t i = 0; (i = text.find('|', i)) != std::string::npos; i += 2) text.replace(i, 1, "\\|");
  return text;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::string parameter_tables_markdown() {
  const Registry& registry = Registry::instance();
  std::vector<std::string> categories(std::begin(kCategories), std::end(kCategories));
  for (const std::string& c : registry.categories())
    if (std::find(categories.begin(), categories.end(), c) == categories.end()) categories.push_back(c);
  std::string out;
  for (const std::string& category : categories) {
    const std::vector<std::string> names = registry.names(category);
    if (names.empty()) continue;
    out.append("### ").append(category).append("\n");
    for (const std::string& name : names) {
      const PluginInfo& info = *registry.find(category, name);
      out.append("\n`").append(name).append("`");
      if (!info.child_categories.empty()) out.append(" (nests: ").append(join_names(info.child_categories)).append(")");
      out.append("\n\n");
      if (info.params.empty()) {
        out.append("No parameters.\n");
        continue;
      }
      out.append("| parameter | type | default | description |\n| --- | --- | --- | --- |\n");
      for (const ParamSpec& p : info.params) {
        out.append("| `").append(p.name).append("` | ").append(to_string(p.type)).append(" | ");
        if (p.default_value)
          out.append("`").append(cell(*p.default_value)).append("`");
        else if (p.type == ParamType::Medium)
          out.append("none (vacuum)");
        else
          out.append("required");
        out.append(" | ").append(cell(p.doc)).append(" |\n");
      }
    }
    out.append("\n");
  }
  return out;
}

}  // namespace caustica
