// The cost of one BSDF sample, eval and pdf, for every material plugin with
// its default parameters: what a path vertex pays for its material. Plugins
// that wrap another BSDF (twosided, mask, bumpmap, ...) wrap a default
// diffuse one (and a checkerboard for a nested texture); those that cannot
// be made from defaults alone are named on stderr and skipped.
// Directions and random numbers are drawn once, up front, so the loops time
// the material alone.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>

#include "core/bsdf/bsdf.h"
#include "core/registry/properties.h"
#include "core/sampling/pcg32.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {

constexpr size_t kInputs = 1024;  // a power of two, so the loops wrap with a mask

struct Inputs {
  std::vector<Vec3> wo, wi;  // wo on the upper hemisphere, wi anywhere on the sphere
  std::vector<float> u_lobe;
  std::vector<Vec2> u;
};

const Inputs& inputs() {
  static const Inputs in = [] {
    Inputs in;
    Pcg32 rng;
    for (size_t i = 0; i < kInputs; ++i) {
      in.wo.push_back(square_to_cosine_hemisphere({rng.next_float(), rng.next_float()}));
      in.wi.push_back(square_to_uniform_sphere({rng.next_float(), rng.next_float()}));
      in.u_lobe.push_back(rng.next_float());
      in.u.push_back({rng.next_float(), rng.next_float()});
    }
    return in;
  }();
  return in;
}

// What a wrapping material gets to wrap.
const std::map<std::string, std::string> kNestedDefaults = {{"bsdf", "diffuse"}, {"texture", "checkerboard"}};

std::shared_ptr<Bsdf> make_bsdf(const std::string& name) {
  const Registry& registry = Registry::instance();
  const PluginInfo* info = registry.find("bsdf", name);
  const SourceLocation where{"default parameters", 0};
  Properties props(*info, where);
  try {
    for (const std::string& category : info->child_categories)
      if (const auto it = kNestedDefaults.find(category); it != kNestedDefaults.end())
        props.add_child({category, registry.create_default<Plugin>(category, it->second, where)}, where);
    return std::dynamic_pointer_cast<Bsdf>(info->create(props));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bsdf_benchmark: skipping %s: %s\n", name.c_str(), e.what());
    return nullptr;
  }
}

void BM_Sample(benchmark::State& state, const Bsdf* bsdf) {
  const Inputs& in = inputs();
  const BsdfContext ctx;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bsdf->sample(ctx, in.wo[i], in.u_lobe[i], in.u[i]));
    i = (i + 1) & (kInputs - 1);
  }
}

void BM_Eval(benchmark::State& state, const Bsdf* bsdf) {
  const Inputs& in = inputs();
  const BsdfContext ctx;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bsdf->eval(ctx, in.wo[i], in.wi[i]));
    i = (i + 1) & (kInputs - 1);
  }
}

void BM_Pdf(benchmark::State& state, const Bsdf* bsdf) {
  const Inputs& in = inputs();
  const BsdfContext ctx;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bsdf->pdf(ctx, in.wo[i], in.wi[i]));
    i = (i + 1) & (kInputs - 1);
  }
}

}  // namespace
}  // namespace caustica

// Benchmarks are registered here rather than statically: the plugins register
// themselves from static initialisers too, in no defined order.
int main(int argc, char** argv) {
  using namespace caustica;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  std::vector<std::shared_ptr<Bsdf>> bsdfs;
  for (const std::string& name : Registry::instance().names("bsdf")) {
    bsdfs.push_back(make_bsdf(name));
    if (const Bsdf* bsdf = bsdfs.back().get()) {
      benchmark::RegisterBenchmark(("BM_Sample/" + name).c_str(), BM_Sample, bsdf);
      benchmark::RegisterBenchmark(("BM_Eval/" + name).c_str(), BM_Eval, bsdf);
      benchmark::RegisterBenchmark(("BM_Pdf/" + name).c_str(), BM_Pdf, bsdf);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
