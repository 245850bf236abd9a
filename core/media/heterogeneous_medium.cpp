// heterogeneous: a medium whose extinction and albedo vary through space,
// each a volume (a gridvolume, or a number or colour that is the same
// everywhere); `scale` multiplies the extinction.
//
//   <medium type="heterogeneous" id="smoke">
//       <volume type="gridvolume" name="sigma_t">
//           <string name="filename" value="smoke.vol"/>
//       </volume>
//       <rgb name="albedo" value="0.8"/>
//       <float name="scale" value="20"/>
//   </medium>
//
// Distances are sampled by delta tracking against majorants bounding the
// extinction over the cells of a coarse grid (majorant_resolution_factor
// voxels to a cell along each axis; 0 is one bound for the whole grid), and
// transmittance is estimated by ratio tracking. Where channels differ the
// tracking is spectral (Kutz et al. 2017): the chance of a real collision
// is the path-weighted average of sigma_t over the majorant, and each
// channel's weight corrects for it, so every channel stays unbiased.

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/media/majorant_grid.h"
#include "core/media/medium.h"
#include "core/media/volume.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Ratio tracking plays Russian roulette once the transmittance falls below
// kRouletteBelow, ending with probability kRouletteEnd.
constexpr float kRouletteBelow = 1e-3f, kRouletteEnd = 0.75f;

class HeterogeneousMedium final : public Medium {
 public:
  explicit HeterogeneousMedium(const Properties& props)
      : sigma_t_(read_volume(props, "sigma_t")),
        albedo_(read_volume(props, "albedo")),
        scale_(props.get_float("scale")) {
    if (!(scale_ >= 0) || !std::isfinite(scale_)) throw props.error("scale", "must be finite and at least 0");
    const int64_t factor = props.get_int("majorant_resolution_factor");
    if (factor < 0) throw props.error("majorant_resolution_factor", "must be at least 0");
    const float headroom = props.get_float("majorant_factor");
    if (!(headroom >= 1) || !std::isfinite(headroom)) throw props.error("majorant_factor", "must be at least 1");
    std::array<int, 3> cells = {1, 1, 1};
    const Vec3 res = sigma_t_->resolution();
    if (factor > 0)
      for (int a = 0; a < 3; ++a) cells[a] = std::max(1, int(std::ceil(res[a] / float(factor))));
    majorants_.emplace(*sigma_t_, cells, scale_, headroom);
    if (!std::isfinite(majorants_->largest()))
      throw props.error("scale", "makes the extinction overflow single precision");
    if (albedo_->max_in({{0, 0, 0}, {1, 1, 1}}) > 1) throw props.error("albedo", "must lie in [0, 1] everywhere");
    read_common(props);
  }

  FreeFlight sample_free_flight(const Ray& ray, float t_max, Color beta, Sampler& sampler) const override {
    const float length = caustica::length(ray.d);
    Color w(1);
    std::optional<float> t_scatter;
    traverse(ray, t_max, [&](float t_begin, float t_end, float majorant) {
      if (!(majorant > 0)) return true;
      for (float t = t_begin;;) {
        t += -std::log1p(-sampler.next_1d()) / (majorant * length);
        if (t >= t_end) return true;
        const Vec3 p = ray.at(t);
        const Color sigma_t = sigma_t_->eval(p) * scale_;
        if (!chromatic_) {
          // Plain delta tracking: the weights of both outcomes are exactly the albedo and 1.
          if (sampler.next_1d() * majorant >= sigma_t.r) continue;
          w = albedo_->eval(p);
          t_scatter = t;
          return false;
        }
        // The path's weight through the tracking so far decides the chance.
        const Color path = beta * w;
        const float mean_path = path.average();
        if (!(mean_path > 0)) return false;
        const float p_real = std::min(1.0f, (sigma_t * path).average() / (majorant * mean_path));
        if (sampler.next_1d() < p_real) {
          w *= sigma_t * albedo_->eval(p) * (1 / (majorant * p_real));
          t_scatter = t;
          return false;
        }
        w *= (Color(majorant) - sigma_t) * (1 / (majorant * (1 - p_real)));
      }
    });
    if (t_scatter) return {true, *t_scatter, w};
    return {false, 0, w.average() > 0 ? w : Color()};
  }

  Color transmittance(const Ray& ray, float t_max, Sampler& sampler) const override {
    const float length = caustica::length(ray.d);
    Color tr(1);
    traverse(ray, t_max, [&](float t_begin, float t_end, float majorant) {
      if (!(majorant > 0)) return true;
      for (float t = t_begin;;) {
        t += -std::log1p(-sampler.next_1d()) / (majorant * length);
        if (t >= t_end) return true;
        const Color null_share = Color(1) - sigma_t_->eval(ray.at(t)) * (scale_ / majorant);
        // Rounding may carry sigma_t a hair past its bound.
        tr *= Color(std::max(0.0f, null_share.r), std::max(0.0f, null_share.g), std::max(0.0f, null_share.b));
        // Russian roulette on what is nearly opaque: products of factors near 1
        // never reach zero once denormal (rounding keeps the smallest one).
        if (tr.max_component() < kRouletteBelow) {
          if (sampler.next_1d() < kRouletteEnd) {
            tr = Color();
            return false;
          }
          tr *= 1 / (1 - kRouletteEnd);
        }
      }
    });
    return tr;
  }

  bool is_homogeneous() const override { return false; }
  bool is_chromatic() const override { return chromatic_; }

 private:
  // A constant extinction has no box: its one majorant holds along the whole ray.
  template <class Visit>
  void traverse(const Ray& ray, float t_max, Visit&& visit) const {
    if (sigma_t_->is_constant()) {
      visit(0.0f, t_max, majorants_->largest());
      return;
    }
    majorants_->traverse({sigma_t_->local(ray.o), sigma_t_->local_vector(ray.d)}, t_max, visit);
  }

  std::shared_ptr<const Volume> sigma_t_, albedo_;
  float scale_;
  bool chromatic_ = sigma_t_->is_chromatic();
  std::optional<MajorantGrid> majorants_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    HeterogeneousMedium, "medium", "heterogeneous",
    {{"sigma_t", ParamType::Volume, "1", "extinction per unit length: a volume, or a number or colour everywhere"},
     {"albedo", ParamType::Volume, "0.75", "single-scattering albedo in [0, 1]: a volume, a number or a colour"},
     {"scale", ParamType::Float, "1", "multiplies the extinction"},
     {"sample_emitters", ParamType::Boolean, "true", "estimate direct light at scattering events"},
     {"majorant_resolution_factor", ParamType::Integer, "8",
      "voxels per majorant cell along each axis (0: one majorant for the whole grid)"},
     {"majorant_factor", ParamType::Float, "1.01", "multiplies every majorant (at least 1)"}},
    {"phase"});

}  // namespace caustica
