// filmic: Hable's filmic curve (the "Uncharted 2" operator, GDC 2010), a
// film-like toe and shoulder applied to each channel:
//   f(x) = (x (A x + C B) + D E) / (x (A x + B) + D F) - E / F
//   out  = f(bias * x) / f(white)
// with A = 0.15 (shoulder), B = 0.50 (linear strength), C = 0.10 (linear
// angle), D = 0.20 (toe strength), E = 0.02, F = 0.30 (toe numerator and
// denominator). Scene values at white / bias map to 1.
//
//   <tonemap type="filmic"/>

#include <algorithm>

#include "core/color/tone_operator.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class FilmicTonemap final : public ToneOperator {
 public:
  explicit FilmicTonemap(const Properties& props)
      : ToneOperator(props), bias_(props.get_float("bias")), white_(props.get_float("white")) {
    if (!(bias_ > 0)) throw props.error("bias", "must be positive");
    if (!(white_ > 0)) throw props.error("white", "must be positive");
  }

  void apply(std::vector<float>& rgb) const override {
    const double inv_white = 1 / curve(white_);
    for (float& v : rgb) v = float(std::min(1.0, curve(double(bias_) * sanitize_radiance(v)) * inv_white));
  }

 private:
  static double curve(double x) {
    constexpr double A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
    return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
  }

  float bias_, white_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(FilmicTonemap, "tonemap", "filmic",
                         tone_operator_params({{"bias", ParamType::Float, "2", "exposure bias before the curve"},
                                               {"white", ParamType::Float, "11.2", "linear white point of the curve"}}),
                         {});

}  // namespace caustica
