// bdpt: bidirectional path tracing (Veach 1997, chapter 10). Each sample
// traces a camera subpath and a light subpath and joins every prefix of one
// to every prefix of the other: s light vertices and t camera vertices make
// strategy (s, t). s = 0 is the camera subpath reaching an emitter by
// itself, s = 1 samples a point on an emitter (next-event estimation), t = 1
// joins a light vertex to the lens and splats where it lands. Every path is
// weighed by multiple importance sampling against all the strategies that
// could have made it, so the estimate stays unbiased while each kind of
// light goes to the strategy that finds it best. Both subpaths scatter in
// participating media as well as at surfaces; a connection to or from a
// point in a medium uses its phase function in place of a BSDF and carries
// the transmittance of the media between in place of visibility.
//
// max_depth counts the segments of the whole path; rr_depth counts the
// vertices of each subpath before Russian roulette may end it. Its default
// is 1, not path's 5: light subpaths then survive each bounce with about
// the share of their power the bounce left them, as sppm's photons do
// (camera subpaths still meet roulette only below rr_threshold). Every
// connection a vertex would have made is work, so shorter light subpaths
// cost less a sample for somewhat more noise: relMSE x time 0.48 to 0.95
// of rr_depth 5's on the Cornell boxes measured (docs/performance.md). `mis` picks the
// heuristic: power (exponent 2) or balance. With strategy_layers = n
// (at most 12) the output also holds, for every path length k = 1 .. n
// segments and each of its k + 1 strategies (s, t) with s + t - 1 = k, the
// strategy's weighted contribution as the layer sStT (channels such as
// s1t2.R, s1t2.G, s1t2.B); a length's layers sum to its share of the beauty.
//
//   <integrator type="bdpt"><integer name="strategy_layers" value="4"/></integrator>

#include <span>
#include <vector>

#include "core/registry/properties.h"
#include "core/render/camera_sample.h"
#include "core/render/light_path_integrator.h"
#include "core/render/path_settings.h"
#include "core/render/sample_wavelengths.h"
#include "core/scene/scene.h"
#include "integrators/bidirectional/camera_connection.h"
#include "integrators/bidirectional/connection.h"
#include "integrators/bidirectional/strategy_weight.h"
#include "integrators/bidirectional/subpath.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// First channel of strategy (s, t) among the layers: paths of k = s + t - 1
// segments have k + 1 strategies, listed by k, then s.
uint32_t layer_channel(int s, int t) {
  const int k = s + t - 1;
  return uint32_t(3 + 3 * ((k - 1) * (k + 2) / 2 + s));
}

class BidirectionalPathTracer final : public LightPathIntegrator {
 public:
  explicit BidirectionalPathTracer(const Properties& props)
      : settings_(read_path_settings(props)),
        heuristic_(read_mis_heuristic(props)),
        layers_(int(props.get_int("strategy_layers"))) {
    if (layers_ < 0 || layers_ > 12) throw props.error("strategy_layers", "must be between 0 and 12");
  }

  std::vector<std::string> channels() const override {
    std::vector<std::string> names{"R", "G", "B"};
    for (int k = 1; k <= layers_; ++k)
      for (int s = 0; s <= k; ++s) {
        const std::string s_text = std::to_string(s), t_text = std::to_string(k + 1 - s);
        for (const char* c : {"R", "G", "B"})
          names.push_back(std::string("s").append(s_text).append("t").append(t_text).append(".").append(c));
      }
    return names;
  }

  // The camera subpath starts from the pixel's camera stream and the light
  // subpath continues in it.
  float sample(const Scene& scene, SampleId id, uint64_t seed, Sampler& sampler, std::span<float> out,
               SplatList& splats) const override {
    std::fill(out.begin(), out.end(), 0.0f);
    thread_local std::vector<PathVertex> camera, light;
    const CameraSample cs = sample_camera_ray(scene, sampler, id.pixel, id.index, seed);
    // In spectral mode both subpaths carry the wavelengths the camera ray
    // draws, and every strategy's value converts to RGB as it is added.
    SampleWavelengths w(scene, sampler);
    Wavelengths* wavelengths = w.get();
    trace_camera_subpath(scene, cs.ray, sampler, settings_, camera, wavelengths);
    compute_densities(scene, camera, heuristic_);
    trace_light_subpath(scene, sampler, cs.ray.time, settings_, light, wavelengths);
    compute_densities(scene, light, heuristic_);

    for (int t = 1; t <= int(camera.size()); ++t)
      for (int s = 0; s <= int(light.size()); ++s) {
        const int k = s + t - 1;
        if (k < 1 || (settings_.max_depth >= 0 && k > settings_.max_depth)) continue;
        if (k == 1 && settings_.hide_emitters) continue;
        const bool layer = k <= layers_;
        if (t == 1) {
          const auto c = connect_to_camera(scene, light, s, sampler, wavelengths);
          if (!c) continue;
          const Color value =
              w.to_rgb(c->value * strategy_weight(scene, std::span(light).first(s), {&c->camera, 1}, s, 1, heuristic_));
          splats.add(c->raster, value);
          if (layer) splats.add(c->raster, value, layer_channel(s, t));
        } else {
          const Color value = w.to_rgb(connect(scene, light, s, camera, t, sampler, wavelengths, heuristic_));
          add(out, 0, value);
          if (layer) add(out, layer_channel(s, t), value);
        }
      }
    return cs.weight;
  }

  bool renders_media() const override { return true; }
  bool renders_spectral() const override { return true; }
  bool renders_motion() const override { return true; }

  std::string plan(const Scene& scene) const override {
    return std::string("bdpt: every (s, t) strategy, weighed by the ") +
           (heuristic_ == MisHeuristic::Power ? "power" : "balance") + " heuristic" +
           (scene.features().caustic_paths ? "; caustics mostly by light tracing (t = 1)" : "") +
           (scene.features().media ? "; media: both subpaths scatter in them, joined through their transmittance" : "");
  }

 private:
  static void add(std::span<float> out, uint32_t channel, Color c) {
    out[channel] += c.r;
    out[channel + 1] += c.g;
    out[channel + 2] += c.b;
  }

  PathSettings settings_;
  MisHeuristic heuristic_;
  int layers_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    BidirectionalPathTracer, "integrator", "bdpt",
    path_settings_params({{"mis", ParamType::String, "power", "MIS heuristic: power (exponent 2) or balance"},
                          {"strategy_layers", ParamType::Integer, "0",
                           "also write each strategy's contribution for paths of up to this many segments (0 to 12)"}},
                         1),
    {});

}  // namespace caustica
