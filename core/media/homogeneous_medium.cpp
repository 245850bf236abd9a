// homogeneous: a medium with the same coefficients everywhere, given as
// extinction and single-scattering albedo (Mitsuba's sigma_t and albedo) or
// as absorption and scattering (sigma_a and sigma_s); `scale` multiplies
// the coefficients (for scenes modelled in other units).
//
//   <medium type="homogeneous" id="fog">
//       <rgb name="albedo" value="0.9, 0.9, 0.9"/>
//       <float name="sigma_t" value="0.5"/>
//       <phase type="hg"><float name="g" value="0.5"/></phase>
//   </medium>
//
// Distances are sampled analytically (exp(-sigma_t s)); with coefficients
// that differ between channels one channel, chosen in proportion to the
// path's weight in it, draws the distance and the weight divides by the
// density averaged over channels with those chances (one-sample multiple
// importance sampling between the channels).

#include <cmath>

#include "core/media/medium.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

Color exp_of(Color c) { return {std::exp(c.r), std::exp(c.g), std::exp(c.b)}; }

class HomogeneousMedium final : public Medium {
 public:
  explicit HomogeneousMedium(const Properties& props) {
    const float scale = props.get_float("scale");
    if (!(scale >= 0) || !std::isfinite(scale)) throw props.error("scale", "must be finite and at least 0");
    const bool absorption_given = props.has("sigma_a") || props.has("sigma_s");
    if (absorption_given && (props.has("sigma_t") || props.has("albedo")))
      throw props.error(props.has("sigma_t") ? "sigma_t" : "albedo",
                        "give either sigma_t and albedo or sigma_a and sigma_s, not both");
    if (absorption_given) {
      const Color sigma_a = read_coefficient(props, "sigma_a"), sigma_s = read_coefficient(props, "sigma_s");
      sigma_s_ = sigma_s * scale;
      sigma_t_ = (sigma_a + sigma_s) * scale;
    } else {
      const Color albedo = props.get_color("albedo");
      for (int c = 0; c < 3; ++c)
        if (!(albedo[c] >= 0 && albedo[c] <= 1)) throw props.error("albedo", "must lie in [0, 1] in every channel");
      sigma_t_ = read_coefficient(props, "sigma_t") * scale;
      sigma_s_ = sigma_t_ * albedo;
    }
    if (!sigma_t_.is_finite()) throw props.error("scale", "makes the coefficients overflow single precision");
    read_common(props);
  }

  FreeFlight sample_free_flight(const Ray& ray, float t_max, Color beta, Sampler& sampler) const override {
    const float length = caustica::length(ray.d);
    const float segment = t_max * length;
    float u = sampler.next_1d();
    int channel = 0;
    Color share(1, 0, 0);  // each channel's chance of drawing the distance
    if (is_chromatic()) {
      const float total = beta.r + beta.g + beta.b;
      share = total > 0 ? beta * (1 / total) : Color(1.0f / 3);
      float start = 0;
      while (channel < 2 && u >= start + share[channel]) start += share[channel++];
      u = std::min((u - start) / share[channel], 0x1.fffffep-1f);
    }
    const float sigma = sigma_t_[channel];
    const float s = sigma > 0 ? -std::log1p(-u) / sigma : kInfinity;
    if (s < segment) {
      const Color tr = exp_of(sigma_t_ * -s);
      const Color pdfs = sigma_t_ * tr * share;
      const float pdf = pdfs.r + pdfs.g + pdfs.b;
      return {true, s / length, pdf > 0 ? tr * sigma_s_ * (1 / pdf) : Color()};
    }
    const Color tr = transmittance_over(segment);
    const Color passes = tr * share;
    const float pass = passes.r + passes.g + passes.b;
    return {false, 0, pass > 0 ? tr * (1 / pass) : Color()};
  }

  Color transmittance(const Ray& ray, float t_max, Sampler&) const override {
    return transmittance_over(t_max * caustica::length(ray.d));
  }

  bool is_homogeneous() const override { return true; }
  bool is_chromatic() const override { return !(sigma_t_.r == sigma_t_.g && sigma_t_.g == sigma_t_.b); }

 private:
  static Color read_coefficient(const Properties& props, const std::string& name) {
    const Color c = props.get_color(name);
    for (int i = 0; i < 3; ++i)
      if (!(c[i] >= 0) || !std::isfinite(c[i]))
        throw props.error(name, "must be finite and at least 0 in every channel");
    return c;
  }

  // exp(-sigma_t d), exactly 1 where sigma_t is 0 even for an infinite d.
  Color transmittance_over(float distance) const {
    const auto channel = [&](float sigma) { return sigma > 0 ? std::exp(-sigma * distance) : 1.0f; };
    return {channel(sigma_t_.r), channel(sigma_t_.g), channel(sigma_t_.b)};
  }

  Color sigma_t_, sigma_s_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    HomogeneousMedium, "medium", "homogeneous",
    {{"albedo", ParamType::Color, "0.75", "single-scattering albedo sigma_s / sigma_t, per channel, in [0, 1]"},
     {"sigma_t", ParamType::Color, "1", "extinction coefficient per unit length, per channel"},
     {"sigma_a", ParamType::Color, "0", "absorption coefficient (instead of albedo and sigma_t)"},
     {"sigma_s", ParamType::Color, "0", "scattering coefficient (instead of albedo and sigma_t)"},
     {"scale", ParamType::Float, "1", "multiplies every coefficient"},
     {"sample_emitters", ParamType::Boolean, "true", "estimate direct light at scattering events"}},
    {"phase"});

}  // namespace caustica
