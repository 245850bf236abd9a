#include "core/render/first_hit_layers.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/render/camera_sample.h"
#include "core/render/sample_scratch.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

std::vector<AovSpec> standard_specs(bool alpha) {
  auto aovs = parse_aov_list("albedo:albedo,normal:sh_normal,depth:depth");
  // Unnamed, coverage is the film's alpha channel "A".
  if (alpha) aovs.push_back({"", AovKind::Coverage});
  return aovs;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

FirstHitLayers::FirstHitLayers(const Scene& scene, uint64_t seed, uint64_t first_sample, const FilmBuffer& beauty,
                               int threads)
    : scene_(scene),
      seed_(seed),
      first_sample_(first_sample),
      beauty_(beauty),
      threads_(threads > 0 ? threads : tbb::this_task_arena::max_concurrency()),
      evaluator_(standard_specs(scene.sensor().film()->output().alpha)) {}

FilmBuffer FirstHitLayers::evaluate(int y_begin, int y_end) const {
  const int width = beauty_.width();
  FilmBuffer band(width, y_end - y_begin, channels(), FilmBuffer::Moments::None);
  tbb::task_arena arena(threads_);
  arena.execute([&] {
    tbb::enumerable_thread_specific<SampleScratch> scratch([&] { return SampleScratch(scene_, 0); });
    tbb::parallel_for(y_begin, y_end, [&](int y) {
      SampleScratch& s = scratch.local();
      s.aov_values.resize(band.channel_count());
      for (int x = 0; x < width; ++x) {
        const uint64_t taken = beauty_.sample_count({x, y});
        for (uint64_t i = first_sample_; i < first_sample_ + taken && i < kAovSamples; ++i) {
          const CameraSample cs = sample_camera_ray(scene_, *s.sampler, {x, y}, i, seed_);
          evaluator_.evaluate(cs.ray, scene_.intersect_for_layers(cs.ray), s.aov_values);
          band.add_sample({{x, y - y_begin}, i}, s.aov_values, cs.weight);
        }
      }
    });
  });
  return band;
}

}  // namespace caustica
