// perspective: a pinhole camera; thinlens: the same with a lens of radius
// aperture_radius focused at focus_distance, for depth of field.
//
// Without a nested film they use an hdrfilm, and without a nested sampler an
// independent sampler, each with its default parameters.
//
//   <sensor type="perspective">
//       <float name="fov" value="39.3"/>
//       <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
//   </sensor>
//   <sensor type="thinlens">
//       <float name="aperture_radius" value="0.05"/>
//       <float name="focus_distance" value="4"/>
//   </sensor>

#include <cmath>

#include "core/camera/perspective_projection.h"
#include "core/camera/sensor.h"
#include "core/geometry/traceable_size.h"
#include "core/math/constants.h"
#include "core/math/transform.h"
#include "core/registry/properties.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Camera space has the lens in the plane z = 0, centred on the origin. A
// ray from lens point l toward the point the pinhole ray of a raster
// position meets at depth focus_distance; with no aperture it is the
// pinhole camera. Importance and densities are those of the thin lens
// (pbrt's derivation): We = 1 / (A A_lens cos^4), with A the window's area
// on the plane z = 1.
class ProjectiveSensor : public Sensor {
 protected:
  ProjectiveSensor(const Properties& props, bool thin_lens)
      : Sensor(props),
        to_world_(props.get_transform("to_world")),
        to_camera_(to_world_.inverse()),
        near_(props.get_float("near_clip")),
        far_(props.get_float("far_clip")),
        projection_(props, *film()) {
    // As Mitsuba: a scale would stretch the field of view and the clip
    // distances without saying so. A mirror (scale -1) keeps lengths.
    for (const Vec3 axis : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
      if (std::abs(length(to_world_.vector(axis)) - 1) > 1e-3f)
        throw props.error("to_world", "must not scale (a camera's field of view is set by fov, not by a scale)");
    if (!(near_ > 0 && far_ > near_)) throw props.error("far_clip", "need 0 < near_clip < far_clip");
    if (thin_lens) {
      lens_radius_ = props.get_float("aperture_radius");
      if (!(lens_radius_ >= 0) || !std::isfinite(lens_radius_))
        throw props.error("aperture_radius", "must be zero or more (zero is a pinhole)");
      if (lens_radius_ > kFarthestFromCamera)
        throw props.error("aperture_radius",
                          "must be at most 1e8: rays from the lens's edge start beyond what "
                          "caustica traces in single precision");
      focus_ = props.has("focus_distance") ? props.get_float("focus_distance") : far_;
      if (!(focus_ > 0) || !std::isfinite(focus_)) throw props.error("focus_distance", "must be positive");
      // A lens too small for its area to be a float is the pinhole.
      if (!(kPi * lens_radius_ * lens_radius_ > 0)) lens_radius_ = 0;
      lens_area_ = lens_radius_ > 0 ? kPi * lens_radius_ * lens_radius_ : 1;
    } else {
      props.get_float("focus_distance");
    }
    origin_ = to_world_.point({0, 0, 0});
    right_ = to_world_.vector({1, 0, 0});
    up_ = to_world_.vector({0, 1, 0});
    forward_ = normalize(to_world_.vector({0, 0, 1}));
  }

 public:
  bool has_lens() const override { return lens_radius_ > 0; }

  Ray generate_ray(Vec2 raster, Vec2 u_lens, float time) const override {
    const Vec3 on_plane = projection_.plane_point(raster);
    if (lens_radius_ == 0) {
      const Vec3 d_local = normalize(on_plane);
      return {origin_, normalize(to_world_.vector(d_local)), far_ / d_local.z, near_ / d_local.z, time};
    }
    const Vec2 lens = square_to_uniform_disk_concentric(u_lens) * lens_radius_;
    // In double: a focus distance or a lens near float's limits squares
    // past them.
    const double x = double(on_plane.x) * focus_ - lens.x, y = double(on_plane.y) * focus_ - lens.y, z = focus_;
    const double length = std::sqrt(x * x + y * y + z * z);
    const Vec3 d_local(float(x / length), float(y / length), float(z / length));
    return {lens_point(lens), normalize(to_world_.vector(d_local)), far_ / d_local.z, near_ / d_local.z, time};
  }

  Color We(const Ray& ray, Vec2* raster) const override {
    const float cos_theta = dot(ray.d, forward_);
    if (cos_theta <= 0 || !to_raster(ray, cos_theta, raster)) return {};
    const float cos2 = cos_theta * cos_theta;
    return Color(1 / (projection_.plane_area() * lens_area_ * cos2 * cos2));
  }

  void pdf_We(const Ray& ray, float* pdf_pos, float* pdf_dir) const override {
    const float cos_theta = dot(ray.d, forward_);
    Vec2 raster;
    *pdf_pos = 0;
    *pdf_dir = 0;
    if (cos_theta <= 0 || !to_raster(ray, cos_theta, &raster)) return;
    *pdf_pos = 1 / lens_area_;
    *pdf_dir = 1 / (projection_.plane_area() * cos_theta * cos_theta * cos_theta);
  }

  ClipPlanes clip_planes() const override { return {origin_, forward_, near_, far_}; }

  std::optional<WiSample> sample_Wi(const ReferencePoint& ref, Vec2 u_lens) const override {
    const Vec3 p_lens =
        lens_radius_ > 0 ? lens_point(square_to_uniform_disk_concentric(u_lens) * lens_radius_) : origin_;
    Vec3 wi = p_lens - ref.p;
    const float dist2 = squared_length(wi);
    if (dist2 == 0) return std::nullopt;
    wi = wi / std::sqrt(dist2);
    // Points outside the clipping planes are invisible to camera rays too.
    const float z = -dot(wi, forward_) * std::sqrt(dist2);
    if (z < near_ || z > far_) return std::nullopt;
    Vec2 raster;
    const Color importance = We({p_lens, -wi, kInfinity}, &raster);
    if (importance.is_black()) return std::nullopt;
    const float cos_lens = dot(-wi, forward_);
    return WiSample{wi, importance, dist2 / (cos_lens * lens_area_), p_lens, raster};
  }

 private:
  Vec3 lens_point(Vec2 lens) const { return origin_ + right_ * lens.x + up_ * lens.y; }

  // Where a ray leaving the lens lands on the film: through the point it
  // meets at the focus depth, as the pinhole would see that point.
  bool to_raster(const Ray& ray, float cos_theta, Vec2* raster) const {
    const Vec3 d = to_camera_.vector(ray.d);
    if (lens_radius_ == 0) return projection_.to_raster(d, raster);
    // The point met at the focus depth, o + d focus / cos, scaled by
    // cos / focus (the pinhole sees only its direction): no overflow for
    // a far focus.
    const Vec3 o = to_camera_.vector(ray.o - origin_);
    return projection_.to_raster(o * (cos_theta / focus_) + d, raster);
  }

  Transform to_world_, to_camera_;
  float near_, far_;
  PerspectiveProjection projection_;
  float lens_radius_ = 0, focus_ = 1, lens_area_ = 1;
  Vec3 origin_, right_, up_, forward_;
};

class PerspectiveSensor final : public ProjectiveSensor {
 public:
  explicit PerspectiveSensor(const Properties& props) : ProjectiveSensor(props, false) {}
};

class ThinLensSensor final : public ProjectiveSensor {
 public:
  explicit ThinLensSensor(const Properties& props) : ProjectiveSensor(props, true) {}
};

std::vector<ParamSpec> projective_params(std::vector<ParamSpec> lens) {
  std::vector<ParamSpec> params = perspective_projection_params();
  params.insert(params.end(), lens.begin(), lens.end());
  const std::vector<ParamSpec> clip = sensor_params();
  params.insert(params.end(), clip.begin(), clip.end());
  params.push_back(
      {"to_world", ParamType::Transform, "", "camera placement; it looks along local +z, with +y up and +x left"});
  return params;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(PerspectiveSensor, "sensor", "perspective",
                         projective_params({{"focus_distance", ParamType::Float, "0",
                                             "accepted for compatibility and ignored; a pinhole is always in focus"}}),
                         {"film", "sampler"});

CAUSTICA_REGISTER_PLUGIN(ThinLensSensor, "sensor", "thinlens",
                         projective_params({{"aperture_radius", ParamType::Float, std::nullopt,
                                             "the lens's radius in scene units"},
                                            {"focus_distance", ParamType::Float, std::nullopt,
                                             "distance from the lens to the plane in focus (default: far_clip)"}}),
                         {"film", "sampler"});

}  // namespace caustica
