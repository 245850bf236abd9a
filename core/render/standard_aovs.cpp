#include "core/render/standard_aovs.h"

#include "core/render/aov_evaluator.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {

std::vector<AovSpec> standard_specs(bool alpha) {
  auto aovs = parse_aov_list("albedo:albedo,normal:sh_normal,depth:depth");
  // Unnamed, coverage is the film's alpha channel "A".
  if (alpha) aovs.push_back({"", AovKind::Coverage});
  return aovs;
}

const AovEvaluator& standard_aovs(bool alpha) {
  static const AovEvaluator without(standard_specs(false)), with(standard_specs(true));
  return alpha ? with : without;
}

}  // namespace

std::vector<std::string> standard_aov_channels(bool alpha) { return standard_aovs(alpha).channels(); }

void add_standard_aovs(const Scene& scene, const CameraSample& cs, SampleId id, FilmBuffer& aovs,
                       std::vector<float>& scratch) {
  if (id.index >= kAovSamples) return;
  scratch.resize(aovs.channel_count());
  standard_aovs(scene.sensor().film()->output().alpha).evaluate(cs.ray, scene.intersect_for_layers(cs.ray), scratch);
  aovs.add_sample(id, scratch, cs.weight);
}

}  // namespace caustica
