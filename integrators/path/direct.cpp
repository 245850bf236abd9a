// direct: direct illumination only (one bounce from the emitters to the camera).
// Emitter samples and BSDF samples are combined by multiple importance
// sampling (power heuristic, accounting for the number of each).
//
// Parameters
//   shading_samples  integer  1      default for both counts below
//   emitter_samples  integer  shading_samples  next-event samples per camera ray
//   bsdf_samples     integer  shading_samples  BSDF samples per camera ray
//   hide_emitters    boolean  false  emitters seen directly appear black
//
//   <integrator type="direct"><integer name="emitter_samples" value="4"/></integrator>

#include "core/bsdf/surface_bsdf.h"
#include "core/registry/properties.h"
#include "core/render/direct_light.h"
#include "core/render/radiance_integrator.h"
#include "core/scene/scene.h"

namespace caustica {
namespace {

int64_t count(const Properties& props, const char* name) {
  const int64_t n = props.has(name) ? props.get_int(name) : props.get_int("shading_samples");
  if (n < 0) throw props.error(name, "must not be negative");
  return n;
}

class DirectIntegrator final : public RadianceIntegrator {
 public:
  explicit DirectIntegrator(const Properties& props)
      : emitter_samples_(count(props, "emitter_samples")),
        bsdf_samples_(count(props, "bsdf_samples")),
        hide_emitters_(props.get_bool("hide_emitters")) {
    if (emitter_samples_ + bsdf_samples_ == 0)
      throw props.error("bsdf_samples", "emitter_samples + bsdf_samples must be positive");
  }

  Color Li(const Scene& scene, Ray ray, Sampler& sampler) const override {
    const auto si = scene.intersect(ray);
    Color L;
    if (!si) {
      if (!hide_emitters_)
        for (const Emitter* env : scene.infinite_emitters()) L += env->Le_infinite(ray.d);
      return L;
    }
    if (const Emitter* e = si->shape->emitter(); e && !hide_emitters_) L += e->L(*si, -ray.d);

    const SurfaceBsdf bsdf(*si->shape->bsdf(), *si, TransportMode::Radiance);
    const Vec3 wo = -ray.d;
    const float nl = float(emitter_samples_), nb = float(bsdf_samples_);
    if (bsdf.lobes() & ~kDelta)
      for (int64_t i = 0; i < emitter_samples_; ++i) {
        const float u_select = sampler.next_1d();
        const Vec2 u_light = sampler.next_2d();
        L += sample_direct_light(scene, *si, bsdf, wo, u_select, u_light, nl, nb) * (1 / nl);
      }
    for (int64_t i = 0; i < bsdf_samples_; ++i) {
      const float u_lobe = sampler.next_1d();
      const auto bs = bsdf.sample(wo, u_lobe, sampler.next_2d());
      if (!bs) continue;
      const Color weight = bs->f * (abs_dot(bs->wi, si->shading.n) / (bs->pdf * nb));
      const Ray next = si->spawn(bs->wi);
      const auto hit = scene.intersect(next);
      if (!hit) {
        for (const Emitter* env : scene.infinite_emitters()) {
          const float w = bs->is_delta()
                              ? 1
                              : bsdf_sample_mis_weight(scene, *env, *si, bs->wi, bs->pdf, SurfaceInteraction{}, nl, nb);
          L += weight * env->Le_infinite(bs->wi) * w;
        }
        continue;
      }
      const Emitter* e = hit->shape->emitter();
      if (!e) continue;
      const Color Le = e->L(*hit, -bs->wi);
      if (Le.is_black()) continue;
      const float w = bs->is_delta() ? 1 : bsdf_sample_mis_weight(scene, *e, *si, bs->wi, bs->pdf, *hit, nl, nb);
      L += weight * Le * w;
    }
    return L;
  }

  std::string describe() const override {
    return "direct emitter_samples=" + std::to_string(emitter_samples_) +
           " bsdf_samples=" + std::to_string(bsdf_samples_) + " hide_emitters=" + (hide_emitters_ ? "true" : "false");
  }

 private:
  int64_t emitter_samples_, bsdf_samples_;
  bool hide_emitters_;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(DirectIntegrator, "integrator", "direct",
                         {{"shading_samples", ParamType::Integer, "1", "default sample count"},
                          {"emitter_samples", ParamType::Integer, "1", "emitter samples per ray"},
                          {"bsdf_samples", ParamType::Integer, "1", "BSDF samples per ray"},
                          {"hide_emitters", ParamType::Boolean, "false", "hide directly visible emitters"}},
                         {});

}  // namespace caustica
