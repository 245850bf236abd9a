#include "core/scene/scene_extent.h"

#include <cmath>
#include <cstdio>

#include "core/geometry/traceable_size.h"

namespace caustica {

std::optional<std::string> scene_extent_problem(const Bounds3& render_bounds) {
  if (render_bounds.empty()) return std::nullopt;
  const float farthest = max_component(max(abs(render_bounds.lo), abs(render_bounds.hi)));
  // In double: a span's square may leave float's range.
  const Vec3 span = render_bounds.hi - render_bounds.lo;
  const double size = std::sqrt(double(span.x) * span.x + double(span.y) * span.y + double(span.z) * span.z);
  char text[240];
  if (!(farthest <= kFarthestFromCamera))
    std::snprintf(text, sizeof text,
                  "the shapes reach %.3g from the camera, and caustica traces only within %.0e of it in single "
                  "precision: scale the scene down (its units are free)",
                  double(farthest), double(kFarthestFromCamera));
  else if (!(size >= kSmallestSceneSize))
    std::snprintf(text, sizeof text,
                  "the shapes span only %.3g, and caustica traces scenes at least %.0e across in single "
                  "precision: scale the scene up (its units are free)",
                  size, double(kSmallestSceneSize));
  else
    return std::nullopt;
  return text;
}

}  // namespace caustica
