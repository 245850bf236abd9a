#include "core/lights/moving_emitter.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace caustica {

MovingEmitter::MovingEmitter(std::shared_ptr<Emitter> still, const std::vector<Transform>& keys)
    : Emitter(*still), still_(std::move(still)), motion_(keys), first_inverse_(keys.front().inverse()) {
  if (!still_->is_delta() || still_->is_infinite())
    throw std::invalid_argument(
        "only point and spot lights can move yet: an area light moves with its shape, which cannot emit yet, and "
        "directional and environment lights stay still");
  if (const size_t k = motion_.first_rescaled_key())
    throw std::invalid_argument("a moving light's keys must share one scale and shear (key " + std::to_string(k) +
                                "'s differs from the first's): a light moves and turns");
}

Transform MovingEmitter::carried(float time) const { return motion_.at(time) * first_inverse_; }

std::optional<LiSample> MovingEmitter::sample_Li(const ReferencePoint& ref, Vec2 u) const {
  const Transform m = carried(ref.time), back = m.inverse();
  const float error = length(ref.p_error);  // a rigid map keeps the error's length
  const Vec3 n = ref.n == Vec3() ? Vec3() : normalize(back.vector(ref.n));
  auto ls = still_->sample_Li({back.point(ref.p), Vec3(error, error, error), n, ref.time}, u);
  if (!ls) return ls;
  ls->wi = normalize(m.vector(ls->wi));
  ls->p = m.point(ls->p);
  return ls;
}

std::optional<LeSample> MovingEmitter::sample_Le(Vec2 u_pos, Vec2 u_dir, float time) const {
  auto le = still_->sample_Le(u_pos, u_dir, time);
  if (!le) return le;
  const Transform m = carried(time);
  le->ray = {m.point(le->ray.o), normalize(m.vector(le->ray.d)), le->ray.t_max, le->ray.t_min, time};
  return le;
}

void MovingEmitter::pdf_Le(const Ray& ray, Vec3 n, float* pdf_pos, float* pdf_dir) const {
  const Transform back = carried(ray.time).inverse();
  still_->pdf_Le({back.point(ray.o), normalize(back.vector(ray.d)), ray.t_max, ray.t_min, ray.time},
                 n == Vec3() ? n : normalize(back.vector(n)), pdf_pos, pdf_dir);
}

}  // namespace caustica
