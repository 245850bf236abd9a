// render_box SCENE OUT.exr SPP SEED: renders SCENE at 8 x 8 pixels on one
// thread and writes its EXR; prints the centre pixel's red and the
// integrator, and the messages of two refusals.
#include <caustica/caustica.h>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc != 5) return 2;
  namespace cs = caustica::api;
  const cs::Scene scene = cs::Scene::load(argv[1], {{"res", "8"}});
  cs::RenderOptions options;
  options.spp = unsigned(std::stoul(argv[3]));
  options.seed = std::stoull(argv[4]);
  options.threads = 1;
  const cs::Render render = cs::render(scene, options);
  render.write_exr(argv[2]);
  std::printf("caustica %s\ncentre red %.9g\n%s\n", cs::version(), render.value(4, 4, "R"),
              render.metadata.at("caustica:integrator").c_str());
  try {
    render.value(0, 0, "no such channel");
  } catch (const std::exception& e) {
    std::printf("refused: %s\n", e.what());
  }
  try {
    cs::Scene::parse("<scene version='3.0.0'><shape type='cube'/>", "broken.xml");
  } catch (const std::exception& e) {
    std::printf("refused: %s\n", e.what());
  }
  return 0;
}
