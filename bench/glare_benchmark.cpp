// Glare's cost: the whole image spread by the eye's PSF (kernel built and
// FFT convolution of three channels) at HD, full HD and 4K, on one thread
// and on every thread TBB may use. Reports megapixels per second. Images
// at least kGlareTwoScaleFrom on each side take the two-scale spread.

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <random>

#include "core/color/glare.h"

namespace caustica {
namespace {

// state.range(0) x range(1) pixels, range(2) threads (0: all).
void WholeImageGlare(benchmark::State& state) {
  const int width = int(state.range(0)), height = int(state.range(1));
  const size_t threads = state.range(2) > 0
                             ? size_t(state.range(2))
                             : tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<float> image(size_t(width) * height * 3);
  for (float& v : image) v = u(rng);
  // A 40 degree horizontal field of view.
  const Glare glare{GlareMode::Whole, 40.0 / width};
  std::vector<float> rgb(image.size());
  for (auto _ : state) {
    // A fresh copy of the image, outside the timing: the tone mapper
    // spreads an image it already holds.
    state.PauseTiming();
    std::copy(image.begin(), image.end(), rgb.begin());
    state.ResumeTiming();
    apply_glare(rgb, width, height, glare);
    benchmark::DoNotOptimize(rgb.data());
  }
  state.counters["Mpixels_per_s"] =
      benchmark::Counter(double(width) * height * 1e-6 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(WholeImageGlare)
    ->Args({1280, 720, 1})
    ->Args({1920, 1080, 1})
    ->Args({3840, 2160, 1})
    ->Args({3840, 2160, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace caustica

BENCHMARK_MAIN();
