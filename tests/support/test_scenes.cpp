#include "tests/support/test_scenes.h"

namespace caustica::test {

LoadedScene scene_from_xml(const std::string& xml, const std::string& name) { return load_scene_string(xml, name); }

FilmBuffer render_scene(const LoadedScene& scene, uint32_t spp, uint64_t seed, int threads, RenderStats* stats) {
  RenderSettings settings;
  settings.spp = spp;
  settings.seed = seed;
  settings.threads = threads;
  settings.aovs = false;
  RenderResult result = RenderJob(scene, settings).run();
  if (stats) *stats = result.stats;
  return std::move(result.film);
}

std::string load_error(const std::string& xml, const std::string& name) {
  try {
    load_scene_string(xml, name);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string scene_test_name(const testing::TestParamInfo<const char*>& info) {
  std::string s = info.param;
  for (char& c : s)
    if (c == '-') c = '_';
  return s;
}

LoadedScene scene_with_integrator(const std::string& name, const std::string& spec, int res) {
  auto scene =
      load_scene(std::string(CAUSTICA_SOURCE_DIR) + "/scenes/" + name + ".xml", {{"res", std::to_string(res)}});
  scene.integrator = make_integrator(spec);
  return scene;
}

}  // namespace caustica::test
