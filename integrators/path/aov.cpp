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
// Rays that miss write zeros. Media and their null boundaries are looked
// through: the values are those of the first surface that scatters light.
// Albedo is the RGB albedo in either transport mode.
//
//   <integrator type="aov"><string name="aovs" value="a:albedo,n:sh_normal"/></integrator>

#include <stdexcept>

#include "core/registry/properties.h"
#include "core/render/aov_evaluator.h"
#include "core/render/pixel_integrator.h"
#include "core/scene/scene.h"

namespace caustica {
namespace {

std::vector<AovSpec> read_aovs(const Properties& props) {
  try {
    return parse_aov_list(props.get_string("aovs"));
  } catch (const std::invalid_argument& e) {
    throw props.error("aovs", e.what());
  }
}

class AovEstimator final : public PixelEstimator {
 public:
  AovEstimator(const AovEvaluator& evaluator, const Scene& scene) : evaluator_(evaluator), scene_(scene) {}
  void sample(const Ray& ray, Sampler&, std::span<float> out) const override {
    evaluator_.evaluate(ray, scene_.intersect_shown(ray), out);
  }

 private:
  const AovEvaluator& evaluator_;
  const Scene& scene_;
};

class AovIntegrator final : public PixelIntegrator {
 public:
  explicit AovIntegrator(const Properties& props) : evaluator_(read_aovs(props)) {}

  std::vector<std::string> channels() const override { return evaluator_.channels(); }
  bool renders_media() const override { return true; }
  bool renders_motion() const override { return true; }
  // The layers carry no light, so spectral transport changes nothing here.
  bool renders_spectral() const override { return true; }

  std::unique_ptr<PixelEstimator> estimator(const Scene& scene, uint64_t) const override {
    return std::make_unique<AovEstimator>(evaluator_, scene);
  }

 private:
  AovEvaluator evaluator_;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    AovIntegrator, "integrator", "aov",
    {{"aovs", ParamType::String, "albedo:albedo,nn:sh_normal,dd:depth",
      "comma-separated name:kind pairs; kinds albedo, sh_normal, geo_normal, position, uv, depth"}},
    {});

}  // namespace caustica
