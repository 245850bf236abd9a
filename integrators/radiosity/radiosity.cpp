// radiosity: the diffuse scene as a linear system over surface elements,
// solved deterministically; an oracle that shares no transport code with the
// Monte Carlo integrators. Each shape is meshed into triangles of at most
// `patch_size`, form factors come from the exact point-to-triangle formula
// at quadrature points with visibility by rays through Embree, and the
// system is solved by Gauss-Seidel; then the elements where radiance varies
// are split and the system is solved again (`refinements` times). Camera
// rays show the radiance interpolated between element corners, or gather
// one bounce from it (`gather` rays per camera ray).
//
//   <integrator type="radiosity"><float name="patch_size" value="0.05"/></integrator>

#include <cstdio>

#include "core/registry/properties.h"
#include "core/render/pixel_integrator.h"
#include "core/scene/scene.h"
#include "integrators/radiosity/radiosity_solution.h"
#include "integrators/radiosity/surface_triangles.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// The patch size that stands for the default 0: a tenth of the scene's diagonal.
constexpr float kDefaultPatchesPerDiagonal = 10;

class RadiosityEstimator final : public PixelEstimator {
 public:
  RadiosityEstimator(const Scene& scene, const RadiositySettings& settings, int gather)
      : solution_(scene, settings), gather_(gather) {}

  void sample(Vec2i /*pixel*/, const Ray& ray, Sampler& sampler, std::span<float> out) const override {
    const Color L = gather_ > 0 ? solution_.gathered(ray, sampler, gather_) : solution_.interpolated(ray);
    out[0] = L.r;
    out[1] = L.g;
    out[2] = L.b;
  }

  std::string summary() const override {
    const RadiosityStats& s = solution_.stats();
    char residual[32];
    std::snprintf(residual, sizeof residual, "%.3g", s.residual);
    return "elements=" + std::to_string(s.elements) + ", unknowns=" + std::to_string(s.unknowns) +
           ", form_factors=" + std::to_string(s.form_factors) + ", levels=" + std::to_string(s.levels) +
           ", sweeps=" + std::to_string(s.sweeps) + ", residual=" + residual;
  }

 private:
  RadiositySolution solution_;
  int gather_;
};

class RadiosityIntegrator final : public PixelIntegrator {
 public:
  explicit RadiosityIntegrator(const Properties& props) {
    if (props.get_int("max_depth") != -1)
      throw props.error("max_depth", "must be -1: radiosity solves for light of every path length");
    settings_.patch_size = props.get_float("patch_size");
    if (!(settings_.patch_size >= 0) || !std::isfinite(settings_.patch_size))
      throw props.error("patch_size", "must be positive (or 0 for a tenth of the scene's diagonal)");
    const int64_t refinements = props.get_int("refinements");
    if (refinements < 0 || refinements > 8) throw props.error("refinements", "must be between 0 and 8");
    settings_.refinements = int(refinements);
    settings_.refine_threshold = props.get_float("refine_threshold");
    if (!(settings_.refine_threshold > 0)) throw props.error("refine_threshold", "must be positive");
    const int64_t rays = props.get_int("visibility_rays");
    if (rays < 1 || rays > 16) throw props.error("visibility_rays", "must be between 1 and 16");
    settings_.visibility_rays = int(rays);
    settings_.tolerance = props.get_float("tolerance");
    if (!(settings_.tolerance > 0 && settings_.tolerance < 1)) throw props.error("tolerance", "must be in (0, 1)");
    const int64_t gather = props.get_int("gather");
    if (gather < 0 || gather > 4096) throw props.error("gather", "must be between 0 and 4096");
    gather_ = int(gather);
  }

  std::unique_ptr<PixelEstimator> estimator(const Scene& scene, uint64_t) const override {
    check_radiosity_scene(scene);
    return std::make_unique<RadiosityEstimator>(scene, settings_for(scene), gather_);
  }

  std::string plan(const Scene& scene) const override {
    return "radiosity: surfaces meshed into elements of at most " + std::to_string(settings_for(scene).patch_size) +
           ", split where radiance varies up to " + std::to_string(settings_.refinements) + " times; camera rays " +
           (gather_ > 0 ? "gather one bounce with " + std::to_string(gather_) + " rays"
                        : "see the interpolated solution") +
           "; no path is traced";
  }

 private:
  RadiositySettings settings_for(const Scene& scene) const {
    RadiositySettings settings = settings_;
    if (settings.patch_size == 0) {
      const Bounds3& b = scene.bounds();
      settings.patch_size = b.empty() ? 1 : length(b.hi - b.lo) / kDefaultPatchesPerDiagonal;
    }
    return settings;
  }

  RadiositySettings settings_;
  int gather_ = 0;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    RadiosityIntegrator, "integrator", "radiosity",
    {{"max_depth", ParamType::Integer, "-1", "accepted for the scenes that set it; only -1 (every path length)"},
     {"patch_size", ParamType::Float, "0", "longest element edge before adaptive splitting (0: diagonal / 10)"},
     {"refinements", ParamType::Integer, "2", "times elements are split where radiance varies, 0 to 8"},
     {"refine_threshold", ParamType::Float, "0.25",
      "split where a corner differs from the element by this times the mean reflected radiance"},
     {"visibility_rays", ParamType::Integer, "4", "rays per pair of elements that estimate visibility, 1 to 16"},
     {"tolerance", ParamType::Float, "0.0001", "residual of the linear system relative to the largest radiance"},
     {"gather", ParamType::Integer, "0", "final-gather rays per camera ray (0: show the interpolated solution)"}},
    {});

}  // namespace caustica
