// spot: a point light shining into a cone around its local +z. Full
// intensity within beam_width of the axis, falling off linearly in angle to
// nothing at cutoff_angle (as Mitsuba's spot does). An optional `texture` is
// projected through the cone, as Mitsuba projects it: a local direction d
// reads (u, v) = (1/2 + d.x / (2 d.z tan(cutoff)), 1/2 + d.y / (2 d.z tan(cutoff))),
// so the texture's square spans the cone's cross-section.
//
//   <emitter type="spot">
//       <rgb name="intensity" value="10"/>
//       <float name="cutoff_angle" value="30"/>
//       <transform name="to_world"><lookat origin="0, 4, 0" target="0, 0, 0" up="0, 0, 1"/></transform>
//   </emitter>

#include <cmath>

#include "core/lights/emission_parameter.h"
#include "core/lights/emitter.h"
#include "core/lights/point_light_li.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class SpotEmitter final : public Emitter {
 public:
  explicit SpotEmitter(const Properties& props)
      : intensity_(read_emission(props, "intensity")),
        texture_(props.has("texture") ? read_nonnegative_texture(props, "texture") : nullptr),
        to_world_(props.get_transform("to_world")),
        to_local_(to_world_.inverse()),
        position_(to_world_.point(Vec3d())) {
    set_measured_emission(props.spectrum("intensity"));
    const float cutoff = props.get_float("cutoff_angle");
    if (!(cutoff > 0 && cutoff <= 180)) throw props.error("cutoff_angle", "must be in (0, 180] degrees");
    const float beam = props.has("beam_width") ? props.get_float("beam_width") : cutoff * 0.75f;
    if (!(beam >= 0 && beam <= cutoff)) throw props.error("beam_width", "must be between 0 and cutoff_angle");
    cutoff_ = cutoff * kPi / 180;
    beam_ = beam * kPi / 180;
    cos_cutoff_ = std::cos(cutoff_);
    cos_beam_ = std::cos(beam_);
    if (texture_ && !(cutoff < 90))
      throw props.error("texture", "needs a cutoff_angle below 90 degrees (it is projected onto a plane)");
    uv_scale_ = 0.5f / std::tan(cutoff_);
  }

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2) const override {
    return point_light_Li(position_, ref, [&](Vec3 d) { return emitted(d); });
  }

  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return 0; }

  std::optional<LeSample> sample_Le(Vec2, Vec2 u_dir, float) const override {
    const Vec3 d = normalize(to_world_.vector(square_to_uniform_cone(u_dir, cos_cutoff_)));
    const Color I = emitted(d);
    if (I.is_black()) return std::nullopt;
    return LeSample{{position_, d, kInfinity}, {}, I, 1, uniform_cone_pdf(cos_cutoff_), {}};
  }

  void pdf_Le(const Ray& ray, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = 1;  // a delta position, reported as sample_Le reports it
    *pdf_dir = falloff(normalize(to_local_.vector(ray.d))) > 0 ? uniform_cone_pdf(cos_cutoff_) : 0;
  }

  // The intensity integrated over the cone: 2 pi [1 - (sin c - sin b) / (c - b)]
  // for the linear fall-off from beam b to cutoff c; 2 pi (1 - cos c) for none.
  // A texture enters by its mean over (u, v), standing for its mean over the
  // cone (light selection needs only a positive weight, not the exact power).
  Color power() const override {
    const double c = cutoff_, b = beam_;
    const double solid =
        c - b > 1e-6 ? 2 * M_PI * (1 - (std::sin(c) - std::sin(b)) / (c - b)) : 2 * M_PI * (1 - std::cos(c));
    return (texture_ ? intensity_ * texture_->mean() : intensity_) * float(solid);
  }
  bool is_delta() const override { return true; }
  // Its cone, widened by a thousandth of a radian against rounding, where
  // to_world keeps angles; a transform that shears or scales unevenly
  // bends the cone, and the bounds then take every direction.
  std::optional<LightBounds> light_bounds() const override {
    LightBounds b;
    b.bounds.expand(position_);
    b.phi = power().average();
    const Vec3 x = to_world_.vector({1, 0, 0}), y = to_world_.vector({0, 1, 0}), z = to_world_.vector({0, 0, 1});
    const float s = length(z);
    const auto near = [&](float a, float e) { return std::abs(a - e) <= 1e-4f * s * s; };
    if (near(dot(x, x), s * s) && near(dot(y, y), s * s) && near(dot(x, y), 0) && near(dot(x, z), 0) &&
        near(dot(y, z), 0) && cutoff_ + 1e-3f < kPi) {
      b.axis = z / s;
      b.cos_theta_o = std::cos(cutoff_ + 1e-3f);
      b.cos_theta_e = 1;
    }
    return b;
  }

 private:
  // The intensity sent along the world direction d.
  Color emitted(Vec3 d) const {
    const Vec3 local = normalize(to_local_.vector(d));
    const float f = falloff(local);
    if (f == 0) return {};
    if (!texture_) return intensity_ * f;
    const Vec2 uv{0.5f + local.x / local.z * uv_scale_, 0.5f + local.y / local.z * uv_scale_};
    return intensity_ * texture_->eval(uv) * f;
  }

  // The fraction of the intensity sent along the local direction d.
  float falloff(Vec3 local) const {
    if (local.z <= cos_cutoff_) return 0;
    if (local.z >= cos_beam_) return 1;
    return (cutoff_ - std::acos(local.z)) / (cutoff_ - beam_);
  }

  Color intensity_;
  std::shared_ptr<Texture> texture_;
  Transform to_world_, to_local_;
  Vec3 position_;
  float cutoff_ = 0, beam_ = 0, cos_cutoff_ = 1, cos_beam_ = 1, uv_scale_ = 0.5f;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    SpotEmitter, "emitter", "spot",
    {{"intensity", ParamType::Color, "1", "radiant intensity on the axis, W/sr per channel"},
     {"cutoff_angle", ParamType::Float, "20", "half-angle in degrees beyond which nothing is emitted"},
     {"beam_width", ParamType::Float, std::nullopt, "half-angle of full intensity (default: 3/4 of cutoff_angle)"},
     {"texture", ParamType::Texture, std::nullopt, "an image projected through the cone, scaling the intensity"},
     {"to_world", ParamType::Transform, "", "placement: the light sits at the origin, shining along local +z"}},
    {});

}  // namespace caustica
