// sppm: stochastic progressive photon mapping (Hachisuka and Jensen 2009),
// the consistent method for scenes where caustics dominate. Every pass is
// one iteration: a round of photons is traced (all indirect light), then
// every pixel traces a camera ray through delta bounces to its visible
// point, adds the emission it met and next-event estimation there, and
// gathers the photons within its own radius. Each pixel keeps its photon
// statistics: N <- N + alpha M, R <- R sqrt(N_new / (N + M)) and
// tau <- (tau + Phi) R_new^2 / R^2, so its radius shrinks where photons are
// dense and the estimate converges as iterations add up. The image is
// D / n + tau / (n photons pi R^2) per pixel after n iterations; the film's
// samples carry nothing, and the filter only places the camera rays.
// Photon rounds and the camera pass run in parallel and are deterministic
// for a seed.
//
// Parameters (path length as in core/render/path_settings.h)
//   max_depth         integer  -1      longest path in segments, photon paths included
//   rr_depth          integer  5       photon vertices before Russian roulette
//   rr_max_survival   float    0.95    upper bound on the survival probability
//   hide_emitters     boolean  false   emitters seen directly appear black
//   photons           integer  100000  photons traced per iteration
//   radius            float    0       initial radius; 0 for 1/200 of the scene's bounding-box diagonal
//   alpha             float    0.7     fraction of new photons kept per iteration, in (0, 1)
//
//   <integrator type="sppm"><integer name="photons" value="200000"/></integrator>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/render/direct_light.h"
#include "core/render/integrator.h"
#include "core/render/path_settings.h"
#include "integrators/photon/photon_tracing.h"
#include "core/scene/scene.h"

namespace caustica {
namespace {

struct PixelState {
  Color direct;  // emission met and next-event estimates, summed over iterations
  Color tau;     // photon flux gathered, rescaled with the radius
  double n = 0;  // photons kept
  float radius = 0;
};

class StochasticProgressivePhotonMapping final : public Integrator {
 public:
  explicit StochasticProgressivePhotonMapping(const Properties& props)
      : settings_(read_path_settings(props)),
        photons_(props.get_int("photons")),
        radius_(props.get_float("radius")),
        alpha_(props.get_float("alpha")) {
    if (photons_ < 1) throw props.error("photons", "must be at least 1");
    if (!(radius_ >= 0)) throw props.error("radius", "must not be negative");
    if (!(alpha_ > 0 && alpha_ < 1)) throw props.error("alpha", "must be in (0, 1)");
  }

  void prepare(const Scene& scene) override {
    const Vec3 diagonal = scene.bounds().hi - scene.bounds().lo;
    const float r0 = radius_ > 0 ? radius_ : std::max(length(diagonal) / 200, 1e-6f);
    width_ = scene.sensor().film()->width();
    pixels_.assign(size_t(width_) * scene.sensor().film()->height(), PixelState{{}, {}, 0, r0});
    iterations_ = 0;
  }

  uint32_t max_pass_samples() const override { return 1; }

  void begin_pass(const Scene& scene, uint32_t pass, uint64_t seed) override {
    float max_radius = 0;
    for (const PixelState& px : pixels_) max_radius = std::max(max_radius, px.radius);
    const PhotonMap map(trace_photons(scene, PhotonPaths::Indirect, uint64_t(photons_), pass, seed, settings_),
                        max_radius);
    const int height = int(pixels_.size() / size_t(width_));
    tbb::parallel_for(0, height, [&](int y) {
      auto sampler = scene.sensor().sampler()->clone();
      for (int x = 0; x < width_; ++x) iterate_pixel(scene, map, *sampler, {x, y}, pass, seed);
    });
    iterations_ = pass + 1;
  }

  void sample(const Scene&, const Ray&, Sampler&, std::span<float> out, SplatList&) const override {
    std::fill(out.begin(), out.end(), 0.0f);
  }

  void finish(const Scene&, FilmBuffer& film) const override {
    if (iterations_ == 0) return;
    std::vector<float> image(pixels_.size() * 3);
    const double emitted = double(iterations_) * double(photons_);
    for (size_t p = 0; p < pixels_.size(); ++p) {
      const PixelState& px = pixels_[p];
      const Color L =
          px.direct / float(iterations_) + px.tau / float(emitted * kPi * double(px.radius) * double(px.radius));
      image[p * 3] = L.r;
      image[p * 3 + 1] = L.g;
      image[p * 3 + 2] = L.b;
    }
    film.set_image(std::move(image));
  }

  std::string plan(const Scene&) const override {
    return std::string("sppm: ") + std::to_string(photons_) +
           " photons per iteration carry all indirect light; emission and next-event estimation at each "
           "pixel's visible point";
  }

  std::string describe() const override {
    return caustica::describe("sppm", settings_) + " photons=" + std::to_string(photons_) +
           " radius=" + std::to_string(radius_) + " alpha=" + std::to_string(alpha_) +
           " iterations=" + std::to_string(iterations_);
  }

 private:
  void iterate_pixel(const Scene& scene, const PhotonMap& map, Sampler& sampler, Vec2i pixel, uint32_t pass,
                     uint64_t seed) {
    PixelState& px = pixels_[size_t(pixel.y) * width_ + pixel.x];
    sampler.start_sample(pixel, pass, seed);
    const FilterSample fs = scene.sensor().film()->filter().sample(sampler.next_2d());
    const Vec2 raster{pixel.x + 0.5f + fs.offset.x, pixel.y + 0.5f + fs.offset.y};
    Ray ray = scene.sensor().generate_ray(raster, scene.sensor().has_lens() ? sampler.next_2d() : Vec2(0.5f, 0.5f));
    Color beta(1), phi;
    double m = 0;
    for (int64_t depth = 0; settings_.max_depth < 0 || depth < settings_.max_depth; ++depth) {
      const auto si = scene.intersect(ray);
      const bool show = depth > 0 || !settings_.hide_emitters;
      if (!si) {
        if (show)
          for (const Emitter* env : scene.infinite_emitters()) px.direct += beta * env->Le_infinite(ray.d);
        break;
      }
      if (const Emitter* emitter = si->shape->emitter(); emitter && show) px.direct += beta * emitter->L(*si, -ray.d);
      if (settings_.max_depth >= 0 && depth + 1 >= settings_.max_depth) break;
      const SurfaceBsdf bsdf(*si->shape->bsdf(), *si, TransportMode::Radiance);
      const Vec3 wo = -ray.d;
      if (bsdf.lobes() & ~kDelta) {
        // The visible point: direct light by shadow rays alone (no BSDF
        // sample follows to share it with), the rest from photons.
        const float u_select = sampler.next_1d();
        px.direct += beta * sample_direct_light(scene, *si, bsdf, wo, u_select, sampler.next_2d(), 1, 0);
        map.for_each_within(si->p, px.radius, [&](const Photon& ph) {
          if (settings_.max_depth >= 0 && int64_t(ph.depth) + depth + 1 > settings_.max_depth) return;
          if (dot(ph.n, si->ng) < 0.5f) return;
          const float cos_g = abs_dot(ph.wi, si->ng);
          if (cos_g == 0) return;
          phi += beta * bsdf.eval(wo, ph.wi) * ph.power * (abs_dot(ph.wi, si->shading.n) / cos_g);
          ++m;
        });
        break;
      }
      const float u_lobe = sampler.next_1d();
      const auto bs = bsdf.sample(wo, u_lobe, sampler.next_2d());
      if (!bs) break;
      beta *= bs->f * (abs_dot(bs->wi, si->shading.n) / bs->pdf);
      ray = si->spawn(bs->wi);
    }
    if (m > 0) {
      const double n_new = px.n + alpha_ * m;
      const double shrink2 = n_new / (px.n + m);  // R_new^2 / R^2
      px.tau = (px.tau + phi) * float(shrink2);
      px.radius = float(px.radius * std::sqrt(shrink2));
      px.n = n_new;
    }
  }

  PathSettings settings_;
  int64_t photons_;
  float radius_, alpha_;
  int width_ = 0;
  std::vector<PixelState> pixels_;
  uint32_t iterations_ = 0;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    StochasticProgressivePhotonMapping, "integrator", "sppm",
    path_settings_params({{"photons", ParamType::Integer, "100000", "photons traced per iteration"},
                          {"radius", ParamType::Float, "0", "initial radius, 0 to derive it from the scene"},
                          {"alpha", ParamType::Float, "0.7", "fraction of new photons kept, in (0, 1)"}}),
    {});

}  // namespace caustica
