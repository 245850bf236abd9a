// reinhard: the global photographic tone reproduction operator (Reinhard et
// al. 2002). With Lw a pixel's luminance and L_avg the image's log-average
// luminance exp(mean(log(delta + Lw))), the scaled luminance
//   L = key / L_avg * Lw
// is compressed to
//   Ld = L (1 + L / L_white^2) / (1 + L),
// and the pixel's RGB is scaled by Ld / Lw (hue is kept). Values at L_white
// map to 1; L_white = 0 takes the image's largest scaled luminance times
// (1 - burn)^2, as Mitsuba 0.x's ldrfilm does: burn 0 keeps the brightest
// pixel just white, burn 1 whites out everything.
//
//   <tonemap type="reinhard"><float name="key" value="0.18"/></tonemap>

#include <algorithm>
#include <cmath>

#include "core/color/tone_operator.h"
#include "core/math/color.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class ReinhardTonemap final : public ToneOperator {
 public:
  explicit ReinhardTonemap(const Properties& props)
      : ToneOperator(props),
        key_(props.get_float("key")),
        white_(props.get_float("white")),
        burn_(props.get_float("burn")) {
    if (!(key_ > 0)) throw props.error("key", "must be positive");
    if (!(white_ >= 0)) throw props.error("white", "must not be negative");
    if (!(burn_ >= 0 && burn_ <= 1)) throw props.error("burn", "must be between 0 and 1");
  }

  void apply(std::vector<float>& rgb) const override {
    for (float& v : rgb) v = sanitize_radiance(v);
    const size_t pixels = rgb.size() / 3;
    if (pixels == 0) return;
    // Small offset so black pixels do not send the log-average to zero.
    constexpr double kDelta = 1e-6;
    double log_sum = 0;
    for (size_t p = 0; p < pixels; ++p) log_sum += std::log(kDelta + luminance(rgb, p));
    const double log_average = std::exp(log_sum / double(pixels));
    const double scale = key_ / log_average;
    double white = white_;
    if (white == 0) {
      for (size_t p = 0; p < pixels; ++p) white = std::max(white, scale * luminance(rgb, p));
      const double kept = std::max(1e-8, 1.0 - burn_);
      white *= kept * kept;
    }
    const double inv_white2 = white > 0 ? 1 / (white * white) : 0;
    for (size_t p = 0; p < pixels; ++p) {
      const double Lw = luminance(rgb, p);
      if (Lw <= 0) continue;
      const double L = scale * Lw;
      const double Ld = L * (1 + L * inv_white2) / (1 + L);
      for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = float(std::min(1.0, rgb[p * 3 + c] * (Ld / Lw)));
    }
  }

 private:
  static double luminance(const std::vector<float>& rgb, size_t p) {
    return Color(rgb[p * 3], rgb[p * 3 + 1], rgb[p * 3 + 2]).luminance();
  }

  float key_, white_, burn_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    ReinhardTonemap, "tonemap", "reinhard",
    tone_operator_params(
        {{"key", ParamType::Float, "0.18", "key value: where the log-average luminance lands (middle grey)"},
         {"white", ParamType::Float, "0", "scaled luminance that maps to white; 0: the image maximum"},
         {"burn", ParamType::Float, "0", "with white 0: the maximum is scaled by (1 - burn)^2, in [0, 1]"}}),
    {});

}  // namespace caustica
