// perspective: a pinhole camera.
//
// Without a nested film it uses an hdrfilm, and without a nested sampler an
// independent sampler, each with its default parameters.
//
//   <sensor type="perspective">
//       <float name="fov" value="39.3"/>
//       <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
//   </sensor>

#include <cmath>

#include "core/camera/sensor.h"
#include "core/math/constants.h"
#include "core/math/transform.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {

template <class T>
std::shared_ptr<T> child_or_default(const Properties& props, const char* category, const char* name) {
  if (auto c = props.child<T>(category)) return c;
  return Registry::instance().create_default<T>(category, name, props.where());
}

class PerspectiveSensor final : public Sensor {
 public:
  explicit PerspectiveSensor(const Properties& props)
      : to_world_(props.get_transform("to_world")),
        to_camera_(to_world_.inverse()),
        near_(props.get_float("near_clip")),
        far_(props.get_float("far_clip")) {
    set_film_and_sampler(child_or_default<Film>(props, "film", "hdrfilm"),
                         child_or_default<Sampler>(props, "sampler", "independent"));
    props.get_float("focus_distance");
    // As Mitsuba: a scale would stretch the field of view and the clip
    // distances without saying so. A mirror (scale -1) keeps lengths.
    for (const Vec3 axis : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
      if (std::abs(length(to_world_.vector(axis)) - 1) > 1e-3f)
        throw props.error("to_world", "must not scale (a camera's field of view is set by fov, not by a scale)");
    const float fov = props.get_float("fov");
    if (!(fov > 0 && fov < 180)) throw props.error("fov", "must be between 0 and 180 degrees");
    if (!(near_ > 0 && far_ > near_)) throw props.error("far_clip", "need 0 < near_clip < far_clip");
    const Vec2i full = film()->full_size(), crop = film()->crop_offset();
    const float w = float(full.x), h = float(full.y);
    // As Mitsuba: the principal point's offset from the film's centre, in
    // fractions of the film's width and height.
    const float ppx = props.get_float("principal_point_offset_x"), ppy = props.get_float("principal_point_offset_y");
    if (!std::isfinite(ppx)) throw props.error("principal_point_offset_x", "must be finite");
    if (!std::isfinite(ppy)) throw props.error("principal_point_offset_y", "must be finite");
    // Raster positions of the crop window map to [0, 1]^2 over the film as
    // u = (raster + crop offset) / size + principal point offset.
    size_ = {w, h};
    crop_ = {float(crop.x), float(crop.y)};
    principal_point_ = {ppx, ppy};
    const std::string axis = props.get_string("fov_axis");
    const float t = std::tan(fov * kPi / 360);
    if (axis == "x" || (axis == "smaller" && w <= h) || (axis == "larger" && w > h)) {
      tan_x_ = t;
      tan_y_ = t * h / w;
    } else if (axis == "y" || axis == "smaller" || axis == "larger") {
      tan_y_ = t;
      tan_x_ = t * w / h;
    } else if (axis == "diagonal") {
      const float d = std::sqrt(w * w + h * h);
      tan_x_ = t * w / d;
      tan_y_ = t * h / d;
    } else {
      throw props.error("fov_axis", "must be x, y, diagonal, smaller or larger, not '" + axis + "'");
    }
    origin_ = to_world_.point({0, 0, 0});
    forward_ = normalize(to_world_.vector({0, 0, 1}));
    // The crop window's part of the image plane at distance 1: importance
    // integrates to one over what is rendered.
    image_plane_area_ = 4 * tan_x_ * tan_y_ * (float(film()->width()) / w) * (float(film()->height()) / h);
  }

  Ray generate_ray(Vec2 raster, Vec2) const override {
    const Vec2 u{(raster.x + crop_.x) / size_.x + principal_point_.x,
                 (raster.y + crop_.y) / size_.y + principal_point_.y};
    const Vec3 local{-(2 * u.x - 1) * tan_x_, -(2 * u.y - 1) * tan_y_, 1};
    const Vec3 d_local = normalize(local);
    const Vec3 d = normalize(to_world_.vector(d_local));
    return {origin_, d, far_ / d_local.z, near_ / d_local.z};
  }

  Color We(const Ray& ray, Vec2* raster) const override {
    const float cos_theta = dot(ray.d, forward_);
    if (cos_theta <= 0 || !to_raster(ray.d, raster)) return {};
    const float cos2 = cos_theta * cos_theta;
    return Color(1 / (image_plane_area_ * cos2 * cos2));
  }

  void pdf_We(const Ray& ray, float* pdf_pos, float* pdf_dir) const override {
    const float cos_theta = dot(ray.d, forward_);
    Vec2 raster;
    *pdf_pos = 0;
    *pdf_dir = 0;
    if (cos_theta <= 0 || !to_raster(ray.d, &raster)) return;
    *pdf_pos = 1;
    *pdf_dir = 1 / (image_plane_area_ * cos_theta * cos_theta * cos_theta);
  }

  ClipPlanes clip_planes() const override { return {origin_, forward_, near_, far_}; }

  std::optional<WiSample> sample_Wi(const ReferencePoint& ref, Vec2) const override {
    Vec3 wi = origin_ - ref.p;
    const float dist2 = squared_length(wi);
    if (dist2 == 0) return std::nullopt;
    wi = wi / std::sqrt(dist2);
    // Points outside the clipping planes are invisible to camera rays too.
    const float z = -dot(wi, forward_) * std::sqrt(dist2);
    if (z < near_ || z > far_) return std::nullopt;
    Vec2 raster;
    const Color importance = We({origin_, -wi, kInfinity}, &raster);
    if (importance.is_black()) return std::nullopt;
    const float cos_lens = dot(-wi, forward_);
    return WiSample{wi, importance, dist2 / cos_lens, origin_, raster};
  }

 private:
  bool to_raster(Vec3 d_world, Vec2* raster) const {
    const Vec3 local = to_camera_.vector(d_world);
    if (local.z <= 0) return false;
    const float x = local.x / local.z, y = local.y / local.z;
    raster->x = ((1 - x / tan_x_) * 0.5f - principal_point_.x) * size_.x - crop_.x;
    raster->y = ((1 - y / tan_y_) * 0.5f - principal_point_.y) * size_.y - crop_.y;
    return raster->x >= 0 && raster->x < film()->width() && raster->y >= 0 && raster->y < film()->height();
  }

  Transform to_world_, to_camera_;
  float near_, far_;
  float tan_x_ = 1, tan_y_ = 1;
  Vec2 size_{1, 1}, crop_, principal_point_;
  Vec3 origin_, forward_;
  float image_plane_area_ = 4;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    PerspectiveSensor, "sensor", "perspective",
    {{"fov", ParamType::Float, "39.597755", "field of view in degrees along fov_axis (a 50 mm lens on 35 mm film)"},
     {"fov_axis", ParamType::String, "x", "axis the fov applies to: x, y, diagonal, smaller or larger"},
     {"near_clip", ParamType::Float, "0.01", "near plane distance"},
     {"far_clip", ParamType::Float, "10000", "far plane distance"},
     {"focus_distance", ParamType::Float, "0", "accepted for compatibility and ignored; a pinhole is always in focus"},
     {"principal_point_offset_x", ParamType::Float, "0",
      "principal point's offset from the film's centre, in film widths (a shifted lens)"},
     {"principal_point_offset_y", ParamType::Float, "0", "the same downward, in film heights"},
     {"to_world", ParamType::Transform, "", "camera placement; it looks along local +z, with +y up and +x left"}},
    {"film", "sampler"});

}  // namespace caustica
