// aov: arbitrary output variables at the first surface the camera sees,
// noise-free inputs for denoisers and compositing.
//
// `aovs` lists comma-separated name:kind pairs; each pair writes the layer
// `name` with the kind's channels:
//   albedo      the BSDF's albedo (reflectance) seen from the ray: name.R, name.G, name.B
//   sh_normal   shading normal, world space: name.X, name.Y, name.Z
//   geo_normal  geometric normal, world space: name.X, name.Y, name.Z
//   position    hit point, world space: name.X, name.Y, name.Z
//   uv          surface coordinates: name.U, name.V
//   depth       distance from the camera along the ray: name.T
//   coverage    1 where the ray meets a surface: name.A
//   dp_du       the surface's tangent along u, world space: name.X, name.Y, name.Z
//   dp_dv       the same along v
//   prim_index  the primitive met within its shape (a mesh's triangle): name.I
//   shape_index the shape met, by its place among the scene's shapes: name.I
//   boundary_test Mitsuba 3's soft indicator of the shape's silhouette and
//               edges (0 there, positive elsewhere; 1 on a miss): name
// Rays that miss write zeros. Media and their null boundaries are looked
// through: the values are those of the first surface that scatters light.
// Albedo is the RGB albedo in either transport mode. Indices are exact up to
// 2^24, and mean nothing where a pixel's samples meet several primitives.
//
// Nested integrators, each named, are rendered along (as in Mitsuba 3):
// theirs are the first channels, each of theirs prefixed by its name
// (my_image.R, my_image.G, my_image.B), the layers after. Each must estimate
// pixel by pixel from the camera (path, volpath, direct, guided_path, photon,
// radiosity); they draw from the pixel's sampler in turn.
//
//   <integrator type="aov">
//       <string name="aovs" value="a:albedo,n:sh_normal"/>
//       <integrator type="path" name="my_image"/>
//   </integrator>

#include <algorithm>
#include <stdexcept>

#include "core/registry/properties.h"
#include "core/render/aov_evaluator.h"
#include "core/render/pixel_integrator.h"
#include "core/scene/scene.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::vector<AovSpec> read_aovs(const Properties& props) {
  try {
    return parse_aov_list(props.get_string("aovs"));
  } catch (const std::invalid_argument& e) {
    throw props.error("aovs", e.what());
  }
}

// A nested integrator and the name that prefixes its channels.
struct Nested {
  std::string name;
  std::shared_ptr<const PixelIntegrator> integrator;
};

std::vector<Nested> read_nested(const Properties& props) {
  std::vector<Nested> out;
  for (const auto& [integrator, name] : props.children_named<Integrator>("integrator")) {
    auto pixel = std::dynamic_pointer_cast<const PixelIntegrator>(integrator);
    if (!pixel)
      throw SceneError(props.where(),
                       "a nested integrator of aov must estimate pixel by pixel from the camera "
                       "(path, volpath, direct, guided_path, photon or radiosity), which '" +
                           integrator->plugin_name() + "' does not");
    if (name.empty())
      throw SceneError(props.where(),
                       "a nested integrator of aov needs a name (name=\"...\"): it prefixes its channels");
    for (const Nested& n : out)
      if (n.name == name) throw SceneError(props.where(), "two nested integrators of aov are named '" + name + "'");
    out.push_back({name, std::move(pixel)});
  }
  return out;
}

class AovEstimator final : public PixelEstimator {
 public:
  AovEstimator(const AovEvaluator& evaluator, const Scene& scene, const std::vector<Nested>& nested, uint64_t seed)
      : evaluator_(evaluator), scene_(scene) {
    for (const Nested& n : nested) {
      estimators_.push_back(n.integrator->estimator(scene, seed));
      widths_.push_back(n.integrator->channels().size());
    }
  }

  bool begin_pass(const PassRange& range, const std::atomic<bool>* stop) override {
    for (const auto& e : estimators_)
      if (!e->begin_pass(range, stop)) return false;
    return true;
  }
  uint32_t max_pass_samples() const override {
    uint32_t most = 16;
    for (const auto& e : estimators_) most = std::min(most, e->max_pass_samples());
    return most;
  }
  std::optional<float> pass_time() const override {
    for (const auto& e : estimators_)
      if (const auto time = e->pass_time()) return time;
    return std::nullopt;
  }

  void sample(Vec2i pixel, const Ray& ray, Sampler& sampler, std::span<float> out) const override {
    size_t at = 0;
    for (size_t i = 0; i < estimators_.size(); ++i) {
      estimators_[i]->sample(pixel, ray, sampler, out.subspan(at, widths_[i]));
      at += widths_[i];
    }
    evaluator_.evaluate(ray, scene_.intersect_shown(ray), out.subspan(at), &scene_);
  }

  std::string summary() const override {
    std::string out;
    for (const auto& e : estimators_)
      if (const std::string s = e->summary(); !s.empty()) out += (out.empty() ? "" : "; ") + s;
    return out;
  }

 private:
  const AovEvaluator& evaluator_;
  const Scene& scene_;
  std::vector<std::unique_ptr<PixelEstimator>> estimators_;
  std::vector<size_t> widths_;
};

class AovIntegrator final : public PixelIntegrator {
 public:
  explicit AovIntegrator(const Properties& props) : evaluator_(read_aovs(props)), nested_(read_nested(props)) {}

  std::vector<std::string> channels() const override {
    std::vector<std::string> out;
    for (const Nested& n : nested_)
      for (const std::string& c : n.integrator->channels()) out.push_back(n.name + "." + c);
    for (const std::string& c : evaluator_.channels()) out.push_back(c);
    return out;
  }
  std::string plan(const Scene& scene) const override {
    std::string out;
    for (const Nested& n : nested_)
      if (const std::string p = n.integrator->plan(scene); !p.empty())
        out += (out.empty() ? "" : "; ") + n.name + ": " + p;
    return out;
  }
  bool splits_samples() const override { return every(&PixelIntegrator::splits_samples); }
  bool renders_media() const override { return every(&PixelIntegrator::renders_media); }
  bool renders_motion() const override { return every(&PixelIntegrator::renders_motion); }
  // The layers carry no light, so spectral transport changes nothing there.
  bool renders_spectral() const override { return every(&PixelIntegrator::renders_spectral); }

  std::unique_ptr<PixelEstimator> estimator(const Scene& scene, uint64_t seed) const override {
    return std::make_unique<AovEstimator>(evaluator_, scene, nested_, seed);
  }

 private:
  // Whether every nested integrator has the trait (the layers alone have all).
  bool every(bool (PixelIntegrator::*trait)() const) const {
    return std::all_of(nested_.begin(), nested_.end(), [&](const Nested& n) { return (*n.integrator.*trait)(); });
  }

  AovEvaluator evaluator_;
  std::vector<Nested> nested_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    AovIntegrator, "integrator", "aov",
    {{"aovs", ParamType::String, "albedo:albedo,nn:sh_normal,dd:depth",
      "comma-separated name:kind pairs; kinds albedo, sh_normal, geo_normal, position, uv, depth, coverage, dp_du, "
      "dp_dv, duv_dx, duv_dy, prim_index, shape_index, boundary_test"}},
    {"integrator"});

}  // namespace caustica
