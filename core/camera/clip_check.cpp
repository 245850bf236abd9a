#include "core/camera/clip_check.h"

#include <algorithm>
#include <cstdio>

namespace caustica {

std::optional<std::string> clip_warning(const ClipPlanes& clip, const Bounds3& bounds) {
  if (bounds.empty()) return std::nullopt;
  // Depths along the view direction, in double: a far corner's depth must
  // not round onto a clip distance.
  double nearest = 1e300, farthest = -1e300;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner{(i & 1) ? bounds.hi.x : bounds.lo.x, (i & 2) ? bounds.hi.y : bounds.lo.y,
                      (i & 4) ? bounds.hi.z : bounds.lo.z};
    double depth = 0;
    for (int a = 0; a < 3; ++a) depth += (double(corner[a]) - clip.position[a]) * clip.forward[a];
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  char text[200];
  if (farthest < clip.near_clip)
    std::snprintf(text, sizeof text,
                  "the whole scene lies nearer to the camera (depth at most %.3g) than near_clip (%.3g): nothing "
                  "is seen; set near_clip on the sensor",
                  farthest, double(clip.near_clip));
  else if (farthest > clip.far_clip)
    std::snprintf(text, sizeof text,
                  "the scene reaches a depth of %.3g from the camera, beyond far_clip (%.3g): what lies beyond "
                  "is not seen; set far_clip on the sensor",
                  farthest, double(clip.far_clip));
  else if (nearest > 0 && nearest < clip.near_clip)
    std::snprintf(text, sizeof text,
                  "the scene comes within a depth of %.3g of the camera, nearer than near_clip (%.3g): what lies "
                  "nearer is not seen",
                  nearest, double(clip.near_clip));
  else
    return std::nullopt;
  return std::string(text);
}

}  // namespace caustica
