#include "core/render/standard_aovs.h"

#include "core/render/aov_evaluator.h"

namespace caustica {

namespace {

const AovEvaluator& standard_aovs() {
  static const AovEvaluator evaluator(parse_aov_list("albedo:albedo,normal:sh_normal,depth:depth"));
  return evaluator;
}

}  // namespace

std::vector<std::string> standard_aov_channels() { return standard_aovs().channels(); }

void add_standard_aovs(const Scene& scene, const CameraSample& cs, SampleId id, FilmBuffer& aovs,
                       std::vector<float>& scratch) {
  if (id.index >= kAovSamples) return;
  scratch.resize(aovs.channel_count());
  standard_aovs().evaluate(scene, cs.ray, scratch);
  aovs.add_sample(id, scratch, cs.weight);
}

}  // namespace caustica
