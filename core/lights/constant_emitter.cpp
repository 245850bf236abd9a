// constant: a uniform environment, radiance arriving equally from every direction.
//
//   <emitter type="constant"><rgb name="radiance" value="0.5"/></emitter>

#include "core/lights/emission_parameter.h"
#include "core/lights/emitter.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {

class ConstantEmitter final : public Emitter {
 public:
  explicit ConstantEmitter(const Properties& props) : radiance_(read_emission(props, "radiance")) {}

  void prepare(const Bounds3& bounds) override {
    if (bounds.empty()) return;
    center_ = bounds.center();
    radius_ = std::max(length(bounds.hi - center_), 1e-3f) * 1.01f;
  }

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2 u) const override {
    const Vec3 wi = square_to_uniform_sphere(u);
    return LiSample{wi, radiance_, uniform_sphere_pdf(), false, ref.p + wi * (2 * radius_), {}, {}, true};
  }

  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return uniform_sphere_pdf(); }

  Color Le_infinite(Vec3) const override { return radiance_; }

  // Emitted rays start on a disk facing the sampled direction, outside the
  // scene's bounding sphere, so every point of the scene is reached.
  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2 u_dir) const override {
    const Vec3 d = -square_to_uniform_sphere(u_dir);
    const Frame frame = Frame::from_normal(d);
    const Vec2 disk = square_to_uniform_disk_concentric(u_pos);
    const Vec3 o = center_ - d * radius_ + (frame.s * disk.x + frame.t * disk.y) * radius_;
    return LeSample{{o, d, kInfinity}, {}, radiance_, 1 / (kPi * radius_ * radius_), uniform_sphere_pdf(), false};
  }

  void pdf_Le(const Ray&, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = 1 / (kPi * radius_ * radius_);
    *pdf_dir = uniform_sphere_pdf();
  }

  Color power() const override { return radiance_ * (kPi * kPi * radius_ * radius_ * 4); }
  bool is_infinite() const override { return true; }

 private:
  Color radiance_;
  Vec3 center_;
  float radius_ = 1;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(ConstantEmitter, "emitter", "constant",
                         {{"radiance", ParamType::Color, "1", "environment radiance"}}, {});

}  // namespace caustica
