// docs/plugins.md's parameter tables are the declarations' own, and every plugin's
// metadata string follows its declarations.

#include "core/registry/parameter_tables.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::string readme_section() {
  std::ifstream in(std::string(CAUSTICA_SOURCE_DIR) + "/docs/plugins.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str(), begin = "<!-- parameters: begin -->\n", end = "<!-- parameters: end -->";
  const size_t b = s.find(begin), e = s.find(end);
  if (b == std::string::npos || e == std::string::npos || e < b) return "(docs/plugins.md has no parameter markers)";
  return s.substr(b + begin.size(), e - b - begin.size());
}

TEST(ParameterTables, ReadmeHoldsTheDeclarations) {
  EXPECT_EQ(readme_section(), parameter_tables_markdown())
      << "docs/plugins.md's parameter tables differ from the declarations: run scripts/update-plugin-reference.sh";
}

TEST(ParameterTables, EveryDeclaredParameterHasATypeDefaultOrRequiredAndADescription) {
  const std::string tables = parameter_tables_markdown();
  for (const std::string& category : Registry::instance().categories())
    for (const std::string& name : Registry::instance().names(category)) {
      EXPECT_NE(tables.find("\n`" + name + "`"), std::string::npos) << category << " " << name;
      for (const ParamSpec& p : Registry::instance().find(category, name)->params)
        EXPECT_FALSE(p.doc.empty()) << category << " " << name << " " << p.name;
    }
}

// The metadata string lists every scalar parameter declared, in order, at
// the value the plugin used, whether given or left at its default.
TEST(EffectiveParameters, FollowTheDeclarationsWithTheValuesUsed) {
  const PluginInfo* info = Registry::instance().find("integrator", "direct");
  Properties props(*info, {"test.xml", 1});
  props.set("shading_samples", {ValueKind::Integer, int64_t(4), {"test.xml", 2}});
  props.set("bsdf_samples", {ValueKind::Integer, int64_t(2), {"test.xml", 3}});
  const auto plugin = info->create(props);
  EXPECT_EQ(plugin->describe_parameters(),
            "direct emitter_samples=4 bsdf_samples=2 shading_samples=4 hide_emitters=false");
  const PluginInfo* bdpt = Registry::instance().find("integrator", "bdpt");
  EXPECT_EQ(bdpt->create(Properties(*bdpt, {"test.xml", 1}))->describe_parameters(),
            "bdpt max_depth=-1 rr_depth=1 rr_max_survival=0.950000 rr_threshold=0.100000 hide_emitters=false mis=power "
            "strategy_layers=0");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
