#include "core/cli/info_command.h"

#include <cstdio>
#include <map>

#include "core/bsdf/bsdf.h"
#include "core/cli/render_command.h"
#include "core/loader/scene_loader.h"
#include "core/registry/registry.h"

namespace caustica {

void InfoCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("info", "print what the scene holds");
  command_->add_option("scene", scene_, "Mitsuba 3 scene file")->required()->check(CLI::ExistingFile);
  command_->add_option("-D", defines_, "define a scene parameter: -D name=value");
}

int InfoCommand::run() const {
  const auto scene = load_scene(scene_, parse_defines(defines_));
  for (const std::string& warning : scene.warnings) std::fprintf(stderr, "caustica: warning: %s\n", warning.c_str());
  std::map<std::string, int> shape_kinds;
  for (const auto& s : scene->shapes()) ++shape_kinds[s->kind()];
  std::printf("scene: %s\n", scene_.c_str());
  const Film& film = *scene->sensor().film();
  if (film.full_size() == Vec2i{film.width(), film.height()})
    std::printf("film: %dx%d\n", film.width(), film.height());
  else
    std::printf("film: %dx%d, rendering the crop window %dx%d at (%d, %d)\n", film.full_size().x, film.full_size().y,
                film.width(), film.height(), film.crop_offset().x, film.crop_offset().y);
  std::printf("integrator: %s\n", scene.integrator->describe().c_str());
  std::printf("shapes: %zu", scene->shapes().size());
  for (const auto& [kind, n] : shape_kinds) std::printf(" (%s: %d)", kind.c_str(), n);
  int area = 0, delta = 0, infinite = 0;
  for (const auto& e : scene->emitters()) {
    area += e->is_area();
    delta += e->is_delta();
    infinite += e->is_environment();  // a directional light counts as delta
  }
  std::printf("\nemitters: %zu (area: %d, delta: %d, environment: %d)\n", scene->emitters().size(), area, delta,
              infinite);
  // Stored relative to the camera; shown in the scene file's coordinates.
  const Bounds3& b = scene->bounds();
  const Vec3d o = scene->render_origin();
  std::printf("bounds: (%g, %g, %g) - (%g, %g, %g)\n", o.x + b.lo.x, o.y + b.lo.y, o.z + b.lo.z, o.x + b.hi.x,
              o.y + b.hi.y, o.z + b.hi.z);
  std::printf("%s", describe(scene->features()).c_str());
  std::printf("what each integrator does with it (default parameters):\n");
  for (const std::string& name : Registry::instance().names("integrator")) {
    const auto integrator = make_integrator(name);
    if (scene->features().medium_walk && !integrator->renders_media()) {
      std::printf("  %s: cannot render it (no participating media or null surfaces yet)\n", name.c_str());
      continue;
    }
    if (scene->features().light_path_only_lights > 0 && !integrator->traces_all_light_from_lights()) {
      std::printf("  %s: cannot render it (its directionalarea light is seen by light tracing only)\n", name.c_str());
      continue;
    }
    const std::string plan = integrator->plan(*scene);
    if (!plan.empty()) std::printf("  %s\n", plan.c_str());
  }
  return 0;
}

}  // namespace caustica
