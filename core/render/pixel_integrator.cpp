#include "core/render/pixel_integrator.h"

#include <vector>

#include "core/render/camera_sample.h"
#include "core/render/pass_schedule.h"
#include "core/render/pixel_loop.h"
#include "core/render/renderer.h"
#include "core/render/tiles.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

class PixelRun final : public IntegratorRun {
 public:
  PixelRun(const Scene& scene, uint64_t seed, std::unique_ptr<PixelEstimator> estimator, size_t channels)
      : scene_(scene),
        seed_(seed),
        estimator_(std::move(estimator)),
        channels_(channels),
        tiles_(make_tiles(scene.sensor().film()->width(), scene.sensor().film()->height())) {}

  uint32_t max_pass_samples() const override { return estimator_->max_pass_samples(); }

  bool run_pass(PassRange range, const PassTarget& target) override {
    if (!estimator_->begin_pass(range, target.stop)) return false;
    for_each_camera_sample(
        scene_, seed_, tiles_, range.first, range.count, channels_, nullptr, estimator_->pass_time(),
        [&](Vec2i pixel, uint64_t i, const CameraSample& cs, SampleScratch& s) {
          estimator_->sample(pixel, cs.ray, *s.sampler, s.values);
          target.film.add_sample({pixel, i}, s.values, cs.weight);
        },
        [&](const Tile& tile) {
          if (target.progress) target.progress->pixel_samples += range.count * tile.pixels();
        });
    return true;
  }

  ReplayedSample replay(Vec2i pixel, uint64_t index) override {
    estimator_->begin_pass({pass_containing(index, estimator_->max_pass_samples()).number, index, 1}, nullptr);
    auto sampler = scene_.sensor().sampler()->clone();
    ReplayedSample out{std::vector<float>(channels_), {}};
    const CameraSample cs = sample_camera_ray(scene_, *sampler, pixel, index, seed_, estimator_->pass_time());
    estimator_->sample(pixel, cs.ray, *sampler, out.values);
    return out;
  }

  std::string summary() const override { return estimator_->summary(); }

 private:
  const Scene& scene_;
  uint64_t seed_;
  std::unique_ptr<PixelEstimator> estimator_;
  size_t channels_;
  std::vector<Tile> tiles_;
};

class RadianceEstimator final : public PixelEstimator {
 public:
  RadianceEstimator(const RadianceIntegrator& integrator, const Scene& scene)
      : integrator_(integrator), scene_(scene) {}

  void sample(Vec2i /*pixel*/, const Ray& ray, Sampler& sampler, std::span<float> out) const override {
    const Color L = integrator_.Li(scene_, ray, sampler);
    out[0] = L.r;
    out[1] = L.g;
    out[2] = L.b;
  }

 private:
  const RadianceIntegrator& integrator_;
  const Scene& scene_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::unique_ptr<IntegratorRun> PixelIntegrator::start(const Scene& scene, uint64_t seed) const {
  return std::make_unique<PixelRun>(scene, seed, estimator(scene, seed), channels().size());
}

std::unique_ptr<PixelEstimator> RadianceIntegrator::estimator(const Scene& scene, uint64_t) const {
  return std::make_unique<RadianceEstimator>(*this, scene);
}

}  // namespace caustica
