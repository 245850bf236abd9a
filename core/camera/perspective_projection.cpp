#include "core/camera/perspective_projection.h"

#include <charconv>
#include <cmath>

#include "core/math/constants.h"
#include "core/registry/properties.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

// A 35 mm-equivalent focal length ("50mm" or "50") as a field of view
// across the diagonal of 36 x 24 mm film, as Mitsuba reads it.
float focal_length_fov(const Properties& props) {
  std::string text = props.get_string("focal_length");
  if (text.size() > 2 && text.ends_with("mm")) text.resize(text.size() - 2);
  double f = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), f);
  if (error != std::errc() || end != text.data() + text.size() || !(f > 0) || !std::isfinite(f))
    throw props.error("focal_length", "must be a positive length in millimetres, such as 50mm");
  return float(2 * std::atan(std::sqrt(36.0 * 36 + 24 * 24) / (2 * f)) * 180 / M_PI);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

Vec2 field_of_view_tangents(const Properties& props, float w, float h) {
  if (props.has("fov") && props.has("focal_length"))
    throw props.error("focal_length", "give either fov or focal_length, not both");
  // As Mitsuba: without a fov, a focal length (by default a 50 mm lens).
  const bool by_focal_length = !props.has("fov");
  const float fov = by_focal_length ? focal_length_fov(props) : props.get_float("fov");
  if (!(fov > 0 && fov < 180)) throw props.error("fov", "must be between 0 and 180 degrees");
  const std::string given_axis = props.get_string("fov_axis");
  if (given_axis != "x" && given_axis != "y" && given_axis != "diagonal" && given_axis != "smaller" &&
      given_axis != "larger")
    throw props.error("fov_axis", "must be x, y, diagonal, smaller or larger, not '" + given_axis + "'");
  // A focal length's fov is the diagonal's, whatever fov_axis says (as Mitsuba).
  const std::string axis = by_focal_length ? "diagonal" : given_axis;
  const float t = std::tan(fov * kPi / 360);
  if (axis == "x" || (axis == "smaller" && w <= h) || (axis == "larger" && w > h)) return {t, t * h / w};
  if (axis == "y" || axis == "smaller" || axis == "larger") return {t * w / h, t};
  const float d = std::sqrt(w * w + h * h);
  return {t * w / d, t * h / d};
}

PerspectiveProjection::PerspectiveProjection(const Properties& props, const Film& film) : window_(film) {
  const Vec2 tangents = field_of_view_tangents(props, float(window_.size.x), float(window_.size.y));
  tan_x_ = tangents.x;
  tan_y_ = tangents.y;
  // As Mitsuba: the principal point's offset from the film's centre, in
  // fractions of the film's width and height.
  const float ppx = props.get_float("principal_point_offset_x"), ppy = props.get_float("principal_point_offset_y");
  if (!std::isfinite(ppx)) throw props.error("principal_point_offset_x", "must be finite");
  if (!std::isfinite(ppy)) throw props.error("principal_point_offset_y", "must be finite");
  // A raster position maps to u = film position + principal point offset,
  // and u spans [0, 1]^2 across the field of view.
  principal_point_ = {ppx, ppy};
  // The crop window's part of the plane: importance integrates to one over
  // what is rendered.
  plane_area_ = 4 * tan_x_ * tan_y_ * window_.fraction();
  // Importance is one over this area (times the lens's): it must be a float.
  if (!std::isnormal(plane_area_) || !std::isnormal(1 / plane_area_))
    throw props.error(props.has("fov") ? "fov" : "focal_length",
                      "gives a view too narrow for single precision (its window on the image plane has no area "
                      "as a float)");
}

Vec3 PerspectiveProjection::plane_point(Vec2 raster) const {
  const Vec2 u = window_.to_film(raster) + principal_point_;
  return {-(2 * u.x - 1) * tan_x_, -(2 * u.y - 1) * tan_y_, 1};
}

bool PerspectiveProjection::to_raster(Vec3 d, Vec2* raster) const {
  if (d.z <= 0) return false;
  const float x = d.x / d.z, y = d.y / d.z;
  *raster = window_.to_raster(Vec2{(1 - x / tan_x_) * 0.5f, (1 - y / tan_y_) * 0.5f} - principal_point_);
  return window_.contains(*raster);
}

std::vector<ParamSpec> field_of_view_params() {
  return {
      {"fov", ParamType::Float, std::nullopt, "field of view in degrees along fov_axis (default: from focal_length)"},
      {"fov_axis", ParamType::String, "x", "axis the fov applies to: x, y, diagonal, smaller or larger"},
      {"focal_length", ParamType::String, "50mm",
       "unless fov is given: a 35 mm-equivalent focal length, giving across the film's diagonal the fov it gives "
       "across 36 x 24 mm film's"}};
}

std::vector<ParamSpec> perspective_projection_params() {
  auto p = field_of_view_params();
  p.insert(p.end(), {{"principal_point_offset_x", ParamType::Float, "0",
                      "principal point's offset from the film's centre, in film widths (a shifted lens)"},
                     {"principal_point_offset_y", ParamType::Float, "0", "the same downward, in film heights"}});
  return p;
}

}  // namespace caustica
