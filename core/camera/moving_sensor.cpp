#include "core/camera/moving_sensor.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace caustica {

MovingSensor::MovingSensor(std::shared_ptr<Sensor> still, const std::vector<Transform>& keys)
    : Sensor(*still), still_(std::move(still)), motion_(keys), first_inverse_(keys.front().inverse()) {
  if (const size_t k = motion_.first_rescaled_key())
    throw std::invalid_argument("a moving camera's keys must share one scale and shear (key " + std::to_string(k) +
                                "'s differs from the first's): a camera moves and turns, its view keeps its size");
}

Transform MovingSensor::carried(float time) const { return motion_.at(time) * first_inverse_; }

Ray MovingSensor::to_still(const Ray& ray) const {
  const Transform back = carried(ray.time).inverse();
  return {back.point(ray.o), normalize(back.vector(ray.d)), ray.t_max, ray.t_min, ray.time};
}

Ray MovingSensor::generate_ray(Vec2 raster, Vec2 u_lens, float time) const {
  const Ray still = still_->generate_ray(raster, u_lens, time);
  const Transform m = carried(time);
  return {m.point(still.o), normalize(m.vector(still.d)), still.t_max, still.t_min, time};
}

Color MovingSensor::We(const Ray& ray, Vec2* raster) const { return still_->We(to_still(ray), raster); }

void MovingSensor::pdf_We(const Ray& ray, float* pdf_pos, float* pdf_dir) const {
  still_->pdf_We(to_still(ray), pdf_pos, pdf_dir);
}

std::optional<WiSample> MovingSensor::sample_Wi(const ReferencePoint& ref, Vec2 u) const {
  const Transform m = carried(ref.time), back = m.inverse();
  // A rigid map keeps the error's length, whatever its direction.
  const float error = length(ref.p_error);
  const Vec3 n = ref.n == Vec3() ? Vec3() : normalize(back.vector(ref.n));
  auto ws = still_->sample_Wi({back.point(ref.p), Vec3(error, error, error), n, ref.time}, u);
  if (!ws) return ws;
  ws->wi = normalize(m.vector(ws->wi));
  ws->p_lens = m.point(ws->p_lens);
  return ws;
}

}  // namespace caustica
