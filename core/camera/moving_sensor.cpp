#include "core/camera/moving_sensor.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace caustica {

MovingSensor::MovingSensor(std::shared_ptr<Sensor> still, const std::vector<Transform>& keys)
    : Sensor(*still), still_(std::move(still)), motion_(keys, keys.front()) {
  if (const size_t k = motion_.rescaled_key())
    throw std::invalid_argument("a moving camera's keys must share one scale and shear (key " + std::to_string(k) +
                                "'s differs from the first's): a camera moves and turns, its view keeps its size");
}

Ray MovingSensor::to_still(const Ray& ray) const {
  const Transform back = motion_.at(ray.time).inverse();
  return {back.point(ray.o), normalize(back.vector(ray.d)), ray.t_max, ray.t_min, ray.time};
}

Ray MovingSensor::generate_ray(Vec2 raster, Vec2 u_lens, float time) const {
  const Ray still = still_->generate_ray(raster, u_lens, time);
  const Transform m = motion_.at(time);
  return {m.point(still.o), normalize(m.vector(still.d)), still.t_max, still.t_min, time};
}

Color MovingSensor::We(const Ray& ray, Vec2* raster) const { return still_->We(to_still(ray), raster); }

void MovingSensor::pdf_We(const Ray& ray, float* pdf_pos, float* pdf_dir) const {
  still_->pdf_We(to_still(ray), pdf_pos, pdf_dir);
}

std::optional<WiSample> MovingSensor::sample_Wi(const ReferencePoint& ref, Vec2 u) const {
  const Transform m = motion_.at(ref.time), back = m.inverse();
  const Vec3 p = back.point(ref.p);
  auto ws = still_->sample_Wi({p, carried_error(ref.p_error, p), carried_normal(back, ref.n), ref.time}, u);
  if (!ws) return ws;
  ws->wi = normalize(m.vector(ws->wi));
  ws->p_lens = m.point(ws->p_lens);
  return ws;
}

}  // namespace caustica
