#include "core/lights/moving_emitter.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "core/geometry/offset.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The rotation alone of `m`: an infinitely far light cannot be moved or
// scaled, only turned.
Transform turn_of(const Transform& m) {
  TransformParts parts = TransformParts::of(m);
  parts.s = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  parts.t = {0, 0, 0};
  return parts.transform();
}

std::vector<Transform> turns_of(const std::vector<Transform>& keys) {
  std::vector<Transform> out;
  for (const Transform& key : keys) out.push_back(turn_of(key));
  return out;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

MovingEmitter::MovingEmitter(std::shared_ptr<Emitter> still, const std::vector<Transform>& keys,
                             const Transform& placement)
    : Emitter(*still),
      still_(std::move(still)),
      motion_(still_->is_infinite() ? RigidMotion(turns_of(keys), turn_of(placement)) : RigidMotion(keys, placement)) {
  if (const size_t k = AnimatedTransform(keys).first_rescaled_key())
    throw std::invalid_argument("a moving light's keys must share one scale and shear (key " + std::to_string(k) +
                                "'s differs from the first's): a light moves and turns");
}

void MovingEmitter::prepare(const Bounds3& bounds) {
  still_->prepare(bounds);
  if (still_->is_infinite() && !bounds.empty()) pivot_ = bounds.center();
}

Transform MovingEmitter::at(float time) const {
  if (!still_->is_infinite()) return motion_.at(time);
  return Transform::translate(pivot_) * motion_.at(time) * Transform::translate(-pivot_);
}

Color MovingEmitter::Le_infinite(Vec3 d, float time) const {
  return still_->Le_infinite(normalize(motion_.at(time).inverse().vector(d)), time);
}

std::optional<LiSample> MovingEmitter::sample_Li(const ReferencePoint& ref, Vec2 u) const {
  const Transform m = at(ref.time), back = m.inverse();
  const Vec3 p = back.point(ref.p);
  auto ls = still_->sample_Li({p, carried_error(ref.p_error, p), carried_normal(back, ref.n), ref.time}, u);
  if (!ls) return ls;
  ls->wi = normalize(m.vector(ls->wi));
  ls->p = m.point(ls->p);
  ls->p_error = ls->p_error == Vec3() ? Vec3() : carried_error(ls->p_error, ls->p);
  ls->n = carried_normal(m, ls->n);
  return ls;
}

float MovingEmitter::pdf_Li(const ReferencePoint& ref, Vec3 wi, const SurfaceInteraction& on_light) const {
  const Transform back = at(ref.time).inverse();
  SurfaceInteraction local = on_light;
  local.p = back.point(on_light.p);
  local.ng = carried_normal(back, on_light.ng);
  local.shading.n = carried_normal(back, on_light.shading.n);
  return still_->pdf_Li({back.point(ref.p), ref.p_error, carried_normal(back, ref.n), ref.time},
                        normalize(back.vector(wi)), local);
}

std::optional<LeSample> MovingEmitter::sample_Le(Vec2 u_pos, Vec2 u_dir, float time) const {
  auto le = still_->sample_Le(u_pos, u_dir, time);
  if (!le) return le;
  const Transform m = at(time);
  const Vec3 d = normalize(m.vector(le->ray.d));
  le->n = carried_normal(m, le->n);
  Vec3 o = m.point(le->ray.o);
  // A ray leaving a surface steps off it again past the map's rounding.
  if (le->n != Vec3()) o = offset_ray_origin(o, carried_error({}, o), le->n, d);
  le->ray = {o, d, le->ray.t_max, le->ray.t_min, time};
  return le;
}

void MovingEmitter::pdf_Le(const Ray& ray, Vec3 n, float* pdf_pos, float* pdf_dir) const {
  const Transform back = at(ray.time).inverse();
  still_->pdf_Le({back.point(ray.o), normalize(back.vector(ray.d)), ray.t_max, ray.t_min, ray.time},
                 carried_normal(back, n), pdf_pos, pdf_dir);
}

}  // namespace caustica
