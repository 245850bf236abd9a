// Cost of the sampler's random numbers and of the warps every path vertex uses.

#include <benchmark/benchmark.h>

#include <string>

#include "core/registry/properties.h"
#include "core/sampling/sampler.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {

// At 64 samples per pixel, the Cornell scenes' default.
std::unique_ptr<Sampler> make_sampler(const char* name) {
  const PluginInfo* info = Registry::instance().find("sampler", name);
  Properties props(*info, {"bench", 0});
  props.set("sample_count", {ValueKind::Integer, int64_t(64), {"bench", 0}});
  return std::dynamic_pointer_cast<Sampler>(info->create(props))->clone();
}

void BM_StartSample(benchmark::State& state, const char* name) {
  auto sampler = make_sampler(name);
  uint64_t i = 0;
  for (auto _ : state) {
    sampler->start_sample(SampleKey::camera({int(i & 511), int(i >> 9 & 511)}), i, 0);
    benchmark::DoNotOptimize(sampler->next_1d());
    ++i;
  }
}

// A sample's first 32 draws, as a path of a few bounces makes them.
void BM_Next1D(benchmark::State& state, const char* name) {
  auto sampler = make_sampler(name);
  uint64_t i = 0;
  for (auto _ : state) {
    if (i % 32 == 0) sampler->start_sample(SampleKey::camera({3, 4}), i / 32, 0);
    benchmark::DoNotOptimize(sampler->next_1d());
    ++i;
  }
}

void BM_Next2D(benchmark::State& state, const char* name) {
  auto sampler = make_sampler(name);
  uint64_t i = 0;
  for (auto _ : state) {
    if (i % 16 == 0) sampler->start_sample(SampleKey::camera({3, 4}), i / 16, 0);
    benchmark::DoNotOptimize(sampler->next_2d());
    ++i;
  }
}

[[maybe_unused]] const bool registered = [] {
  for (const char* name : {"independent", "ldsampler", "stratified", "multijitter", "halton"}) {
    benchmark::RegisterBenchmark((std::string("BM_StartSample/") + name).c_str(), BM_StartSample, name);
    benchmark::RegisterBenchmark((std::string("BM_Next1D/") + name).c_str(), BM_Next1D, name);
    benchmark::RegisterBenchmark((std::string("BM_Next2D/") + name).c_str(), BM_Next2D, name);
  }
  return true;
}();

void BM_CosineHemisphere(benchmark::State& state) {
  auto sampler = make_sampler("independent");
  sampler->start_sample(SampleKey::camera({0, 0}), 0, 0);
  for (auto _ : state) benchmark::DoNotOptimize(square_to_cosine_hemisphere(sampler->next_2d()));
}
BENCHMARK(BM_CosineHemisphere);

}  // namespace
}  // namespace caustica
