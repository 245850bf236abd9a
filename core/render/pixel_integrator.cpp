#include "core/render/pixel_integrator.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <vector>

#include "core/render/camera_sample.h"
#include "core/render/pass_schedule.h"
#include "core/render/renderer.h"
#include "core/render/sample_scratch.h"
#include "core/render/tiles.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {

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
    if (!estimator_->begin_pass(range.pass, target.stop)) return false;
    tbb::enumerable_thread_specific<SampleScratch> scratch([&] { return SampleScratch(scene_, channels_); });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles_.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      SampleScratch& s = scratch.local();
      for (size_t t = r.begin(); t != r.end(); ++t) {
        const Tile& tile = tiles_[t];
        for (int y = tile.lo.y; y < tile.hi.y; ++y)
          for (int x = tile.lo.x; x < tile.hi.x; ++x)
            for (uint64_t i = range.first; i < range.first + range.count; ++i) {
              const CameraSample cs = sample_camera_ray(scene_, *s.sampler, {x, y}, i, seed_);
              estimator_->sample(cs.ray, *s.sampler, s.values);
              target.film.add_sample({{x, y}, i}, s.values, cs.weight);
            }
        if (target.progress) target.progress->pixel_samples += range.count * tile.pixels();
      }
    });
    return true;
  }

  ReplayedSample replay(Vec2i pixel, uint64_t index) override {
    estimator_->begin_pass(pass_containing(index, estimator_->max_pass_samples()).number, nullptr);
    auto sampler = scene_.sensor().sampler()->clone();
    ReplayedSample out{std::vector<float>(channels_), {}};
    const CameraSample cs = sample_camera_ray(scene_, *sampler, pixel, index, seed_);
    estimator_->sample(cs.ray, *sampler, out.values);
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

  void sample(const Ray& ray, Sampler& sampler, std::span<float> out) const override {
    const Color L = integrator_.Li(scene_, ray, sampler);
    out[0] = L.r;
    out[1] = L.g;
    out[2] = L.b;
  }

 private:
  const RadianceIntegrator& integrator_;
  const Scene& scene_;
};

}  // namespace

std::unique_ptr<IntegratorRun> PixelIntegrator::start(const Scene& scene, uint64_t seed) const {
  return std::make_unique<PixelRun>(scene, seed, estimator(scene, seed), channels().size());
}

std::unique_ptr<PixelEstimator> RadianceIntegrator::estimator(const Scene& scene, uint64_t) const {
  return std::make_unique<RadianceEstimator>(*this, scene);
}

}  // namespace caustica
