// projector: a point light that projects an image, the reciprocal of the
// perspective camera (Mitsuba 3's projector). It sits at its local origin,
// looking along +z with +x left and +y up, as the camera does; its field of
// view (fov, fov_axis or focal_length, as the camera's) frames the
// `irradiance` texture on the plane z = 1, the texture's aspect ratio
// giving the frame's (a texture without a resolution is square). A local
// direction d in the frame reads the texture at the camera's raster
// mapping, u = (1 - d.x / (d.z tan_x)) / 2, v = (1 - d.y / (d.z tan_y)) / 2,
// and carries the intensity
//
//   I(d) = pi scale T(u, v) / cos^3(theta),   cos(theta) = d.z / |d|,
//
// so that a plane facing the projector at distance D receives the
// irradiance pi scale T / D^2 all over, the image undistorted. Its power is
// pi scale A mean(T), A = 4 tan_x tan_y the frame's area, exactly (u and v
// are linear on the plane). Light paths leave through a point drawn evenly
// on the frame.
//
//   <emitter type="projector">
//       <texture type="bitmap" name="irradiance"><string name="filename" value="slide.png"/></texture>
//       <float name="fov" value="40"/>
//       <transform name="to_world"><lookat origin="0, 2, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
//   </emitter>

#include <cmath>

#include "core/camera/perspective_projection.h"
#include "core/lights/emitter.h"
#include "core/lights/point_light_li.h"
#include "core/math/constants.h"
#include "core/registry/properties.h"
#include "core/texture/texture.h"
#include "core/texture/texture_parameter.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class ProjectorEmitter final : public Emitter {
 public:
  explicit ProjectorEmitter(const Properties& props)
      : irradiance_(read_nonnegative_texture(props, "irradiance")),
        scale_(props.get_float("scale")),
        to_world_(props.get_transform("to_world")),
        to_local_(to_world_.inverse()),
        position_(to_world_.point(Vec3d())) {
    if (!(scale_ >= 0) || !std::isfinite(scale_)) throw props.error("scale", "must not be negative");
    const Vec2i size = irradiance_->resolution().value_or(Vec2i{1, 1});
    const Vec2 tangents = field_of_view_tangents(props, float(size.x), float(size.y));
    tan_x_ = tangents.x;
    tan_y_ = tangents.y;
    area_ = 4 * tan_x_ * tan_y_;
  }

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2) const override {
    return point_light_Li(position_, ref, [&](Vec3 d) { return emitted(d); });
  }

  float pdf_Li(const ReferencePoint&, Vec3, const SurfaceInteraction&) const override { return 0; }

  std::optional<LeSample> sample_Le(Vec2, Vec2 u_dir, float) const override {
    const Vec3 on_frame{(1 - 2 * u_dir.x) * tan_x_, (1 - 2 * u_dir.y) * tan_y_, 1};
    const Vec3 d = normalize(to_world_.vector(on_frame));
    const Color I = emitted(d);
    if (I.is_black()) return std::nullopt;
    return LeSample{{position_, d, kInfinity}, {}, I, 1, frame_pdf(on_frame), {}};
  }

  void pdf_Le(const Ray& ray, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = 1;  // a delta position, reported as sample_Le reports it
    const Vec3 local = to_local_.vector(ray.d);
    *pdf_dir = in_frame(local) ? frame_pdf(local / local.z) : 0;
  }

  Color power() const override { return irradiance_->mean() * (kPi * scale_ * area_); }
  bool is_delta() const override { return true; }

 private:
  // The density, per unit solid angle, of the direction through the frame
  // point p (p.z = 1) drawn evenly on the frame: dA = dw / cos^3.
  float frame_pdf(Vec3 p) const {
    const float cos = 1 / length(p);
    return 1 / (area_ * cos * cos * cos);
  }

  bool in_frame(Vec3 local) const {
    return local.z > 0 && std::abs(local.x) <= tan_x_ * local.z && std::abs(local.y) <= tan_y_ * local.z;
  }

  // The intensity sent along the world direction d.
  Color emitted(Vec3 d) const {
    const Vec3 local = normalize(to_local_.vector(d));
    if (!in_frame(local)) return {};
    const Vec2 uv{0.5f * (1 - local.x / (local.z * tan_x_)), 0.5f * (1 - local.y / (local.z * tan_y_))};
    const float cos = local.z;
    return irradiance_->eval(uv) * (kPi * scale_ / (cos * cos * cos));
  }

  std::shared_ptr<Texture> irradiance_;
  float scale_;
  Transform to_world_, to_local_;
  Vec3 position_;
  float tan_x_ = 1, tan_y_ = 1, area_ = 4;
};

std::vector<ParamSpec> params() {
  auto p = field_of_view_params();
  p.insert(p.end(), {{"irradiance", ParamType::Texture, std::nullopt,
                      "the image projected: irradiance over pi on a plane facing the projector at distance 1"},
                     {"scale", ParamType::Float, "1", "scales the irradiance"},
                     {"to_world", ParamType::Transform, "",
                      "placement: the projector sits at the origin, looking along local +z with +x left and +y up"}});
  return p;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(ProjectorEmitter, "emitter", "projector", params(), {});

}  // namespace caustica
