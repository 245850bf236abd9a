#include "tests/support/test_scenes.h"

namespace caustica::test {

std::unique_ptr<Scene> scene_from_xml(const std::string& xml, const std::string& name) {
  return load_scene_string(xml, name);
}

FilmBuffer render_scene(const Scene& scene, uint32_t spp, uint64_t seed, int threads) {
  FilmBuffer film(scene.sensor().film()->width(), scene.sensor().film()->height(), scene.integrator()->channels());
  RenderOptions options;
  options.spp = spp;
  options.seed = seed;
  options.threads = threads;
  render(scene, options, film);
  return film;
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

}  // namespace caustica::test
