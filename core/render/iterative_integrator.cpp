#include "core/render/iterative_integrator.h"

#include <tbb/parallel_for.h>

#include <stdexcept>
#include <vector>

#include "core/render/renderer.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

class IterativeRun final : public IntegratorRun {
 public:
  IterativeRun(const Scene& scene, std::unique_ptr<IterationState> state) : scene_(scene), state_(std::move(state)) {}

  uint32_t max_pass_samples() const override { return 1; }
  bool variance_known() const override { return false; }

  bool run_pass(PassRange range, const PassTarget& target) override {
    // Statistics kept across iterations make iteration N of a render that
    // starts at N another estimate than iteration N of one that starts at 0.
    if (range.first != iterations_)
      throw std::invalid_argument(
          "an iterative integrator keeps each pixel's statistics across iterations: it renders from iteration 0 "
          "on, not from --first-sample " +
          std::to_string(range.first));
    const Film& film = *scene_.sensor().film();
    for (uint64_t i = range.first; i < range.first + range.count; ++i) {
      if (!state_->iterate(i, target.stop)) return false;
      ++iterations_;
      last_ = i;
      if (target.progress) target.progress->pixel_samples += uint64_t(film.width()) * film.height();
    }
    return true;
  }

  void finish(FilmBuffer& film) override {
    if (iterations_ == 0) return;
    tbb::parallel_for(0, film.height(), [&](int y) {
      for (int x = 0; x < film.width(); ++x) {
        const Color L = state_->estimate({x, y});
        const float values[3] = {L.r, L.g, L.b};
        film.add_sample({{x, y}, last_}, values, 1, iterations_);
      }
    });
  }

  ReplayedSample replay(Vec2i, uint64_t) override {
    throw std::invalid_argument(
        "an iterative integrator keeps each pixel's statistics across iterations: one sample cannot be replayed alone");
  }

  std::string summary() const override { return state_->summary(); }

 private:
  const Scene& scene_;
  std::unique_ptr<IterationState> state_;
  uint32_t iterations_ = 0;
  uint64_t last_ = 0;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::unique_ptr<IntegratorRun> IterativeIntegrator::start(const Scene& scene, uint64_t seed) const {
  return std::make_unique<IterativeRun>(scene, begin(scene, seed));
}

}  // namespace caustica
