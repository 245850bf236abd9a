#include "core/camera/pixel_angle.h"

#include <cmath>
#include <numbers>

#include "core/camera/sensor.h"

namespace caustica {

double degrees_per_pixel(const Sensor& sensor) {
  const float cx = 0.5f * float(sensor.film()->width()), cy = 0.5f * float(sensor.film()->height());
  const Vec3 a = normalize(sensor.generate_ray({cx - 0.5f, cy}, {0.5f, 0.5f}).d);
  const Vec3 b = normalize(sensor.generate_ray({cx + 0.5f, cy}, {0.5f, 0.5f}).d);
  // atan2 keeps its precision where the angle is small, as acos does not.
  return std::atan2(double(length(cross(a, b))), double(dot(a, b))) * 180 / std::numbers::pi;
}

}  // namespace caustica
