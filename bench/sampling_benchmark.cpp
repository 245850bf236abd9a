// Cost of the sampler's random numbers and of the warps every path vertex uses.

#include <benchmark/benchmark.h>

#include "core/registry/properties.h"
#include "core/sampling/sampler.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {

std::unique_ptr<Sampler> independent_sampler() {
  const PluginInfo* info = Registry::instance().find("sampler", "independent");
  return std::dynamic_pointer_cast<Sampler>(info->create(Properties(*info, {"bench", 0})))->clone();
}

void BM_StartSample(benchmark::State& state) {
  auto sampler = independent_sampler();
  uint64_t i = 0;
  for (auto _ : state) {
    sampler->start_sample(SampleKey::camera({int(i & 511), int(i >> 9 & 511)}), i, 0);
    benchmark::DoNotOptimize(sampler->next_1d());
    ++i;
  }
}
BENCHMARK(BM_StartSample);

void BM_Next2D(benchmark::State& state) {
  auto sampler = independent_sampler();
  sampler->start_sample(SampleKey::camera({0, 0}), 0, 0);
  for (auto _ : state) benchmark::DoNotOptimize(sampler->next_2d());
}
BENCHMARK(BM_Next2D);

void BM_CosineHemisphere(benchmark::State& state) {
  auto sampler = independent_sampler();
  sampler->start_sample(SampleKey::camera({0, 0}), 0, 0);
  for (auto _ : state) benchmark::DoNotOptimize(square_to_cosine_hemisphere(sampler->next_2d()));
}
BENCHMARK(BM_CosineHemisphere);

}  // namespace
}  // namespace caustica
