// orthographic: parallel rays along local +z from a film that covers
// [-1, 1] in local x and [-h/w, h/w] in local y (as Mitsuba's does); a scale
// in to_world sets the size of what is seen.
//
//   <sensor type="orthographic">
//       <transform name="to_world">
//           <scale x="2" y="2"/>
//           <lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/>
//       </transform>
//   </sensor>

#include <cmath>

#include "core/camera/film_window.h"
#include "core/camera/sensor.h"
#include "core/math/transform.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Every ray travels along `forward`: the importance is a delta in
// direction times 1 / A per unit area of the film (A its rendered window's
// area in the scene), and a light path reaches the film only by
// projecting onto it along -forward.
class OrthographicSensor final : public Sensor {
 public:
  explicit OrthographicSensor(const Properties& props)
      : Sensor(props), near_(props.get_float("near_clip")), far_(props.get_float("far_clip")), window_(*film()) {
    if (!(near_ >= 0 && far_ > near_)) throw props.error("far_clip", "need 0 <= near_clip < far_clip");
    if (props.has("focus_distance")) props.warn("focus_distance", "is ignored: parallel rays have no focus");
    const Transform to_world = props.get_transform("to_world");
    origin_ = to_world.point({0, 0, 0});
    axis_x_ = to_world.vector({1, 0, 0});
    axis_y_ = to_world.vector({0, 1, 0});
    const Vec3 z = to_world.vector({0, 0, 1});
    // (The loader refuses singular transforms, so no axis is zero.)
    const float lx = length(axis_x_), ly = length(axis_y_);
    forward_ = normalize(z);
    dual_x_ = axis_x_ / (lx * lx);
    dual_y_ = axis_y_ / (ly * ly);
    // Rays leave the film at right angles; a shear would tilt them.
    if (std::abs(dot(axis_x_, axis_y_)) > 1e-3f * lx * ly || std::abs(dot(axis_x_, forward_)) > 1e-3f * lx ||
        std::abs(dot(axis_y_, forward_)) > 1e-3f * ly)
      throw props.error("to_world", "must not shear (the film's axes and the view direction stay at right angles)");
    aspect_y_ = window_.size.y / window_.size.x;
    area_ = lx * ly * 4 * aspect_y_ * window_.fraction();
  }

  Ray generate_ray(Vec2 raster, Vec2, float time) const override {
    const Vec2 u = window_.to_film(raster);
    const float x = 1 - 2 * u.x, y = (1 - 2 * u.y) * aspect_y_;
    return {origin_ + axis_x_ * x + axis_y_ * y, forward_, far_, near_, time};
  }

  // The ray's direction is taken to be `forward` (the delta); what counts
  // is where it leaves the film.
  Color We(const Ray& ray, Vec2* raster) const override {
    if (dot(ray.d, forward_) <= 0 || !to_raster(ray.o, raster)) return {};
    return Color(1 / area_);
  }

  void pdf_We(const Ray& ray, float* pdf_pos, float* pdf_dir) const override {
    Vec2 raster;
    *pdf_pos = dot(ray.d, forward_) > 0 && to_raster(ray.o, &raster) ? 1 / area_ : 0;
    *pdf_dir = 0;  // a delta, which no other strategy can produce
  }

  bool delta_direction() const override { return true; }

  ClipPlanes clip_planes() const override { return {origin_, forward_, near_, far_}; }

  std::optional<WiSample> sample_Wi(const ReferencePoint& ref, Vec2) const override {
    const float depth = dot(ref.p - origin_, forward_);
    if (depth < near_ || depth > far_) return std::nullopt;
    const Vec3 on_film = ref.p - forward_ * depth;
    Vec2 raster;
    if (!to_raster(on_film, &raster)) return std::nullopt;
    return WiSample{-forward_, Color(1 / area_), 1, on_film, raster};
  }

 private:
  // The raster position of a point, projected onto the film along forward.
  bool to_raster(Vec3 p, Vec2* raster) const {
    const Vec3 rel = p - origin_;
    const float x = dot(rel, dual_x_), y = dot(rel, dual_y_);
    *raster = window_.to_raster({(1 - x) * 0.5f, (1 - y / aspect_y_) * 0.5f});
    return window_.contains(*raster);
  }

  float near_, far_;
  FilmWindow window_;
  Vec3 origin_, axis_x_, axis_y_, forward_;
  // The axes over their squared lengths: a point's film coordinates are its
  // dot products with them.
  Vec3 dual_x_, dual_y_;
  float aspect_y_ = 1, area_ = 4;
};

std::vector<ParamSpec> orthographic_params() {
  std::vector<ParamSpec> params = sensor_params();
  params.push_back({"focus_distance", ParamType::Float, std::nullopt, "accepted and ignored (no lens)"});
  params.push_back({"to_world", ParamType::Transform, "",
                    "placement and size: the film spans local x in [-1, 1] and y in [-h/w, h/w], looking along +z"});
  return params;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(OrthographicSensor, "sensor", "orthographic", orthographic_params(), {"film", "sampler"});

}  // namespace caustica
