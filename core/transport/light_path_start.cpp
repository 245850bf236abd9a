#include "core/transport/light_path_start.h"

#include "core/scene/scene.h"

namespace caustica {

std::optional<LightPathStart> start_light_path(const Scene& scene, Sampler& sampler, float time) {
  float u_select = sampler.next_1d();
  const Vec2 u_pos = sampler.next_2d(), u_dir = sampler.next_2d();
  const auto choice = scene.light_selection().sample(u_select);
  if (!choice) return std::nullopt;
  auto le = choice->emitter->sample_Le(u_pos, u_dir, time);
  if (!le || !(le->pdf_pos > 0) || !(le->pdf_dir > 0) || le->Le.is_black()) return std::nullopt;
  le->ray.time = time;
  const float cos = le->n == Vec3() ? 1 : abs_dot(le->n, le->ray.d);
  return LightPathStart{choice->emitter, choice->pmf, *le, le->Le * (cos / (choice->pmf * le->pdf_pos * le->pdf_dir))};
}

}  // namespace caustica
