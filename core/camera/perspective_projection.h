#pragma once

#include <vector>

#include "core/camera/film_window.h"
#include "core/film/film.h"
#include "core/math/vec.h"
#include "core/registry/param_spec.h"

namespace caustica {

class Properties;

// Where a perspective camera's raster positions point, in camera space
// (looking along +z, +x left, +y up): the field of view (fov and fov_axis,
// or a 35 mm-equivalent focal_length), the principal point's offset and the
// film's crop window, all as Mitsuba defines them.
class PerspectiveProjection {
 public:
  PerspectiveProjection(const Properties& props, const Film& film);

  // The point on the plane z = 1 that raster position `raster` sees.
  Vec3 plane_point(Vec2 raster) const;
  // The raster position of camera-space direction d (d.z > 0); false when
  // it falls outside the rendered window.
  bool to_raster(Vec3 d, Vec2* raster) const;
  // The rendered window's area on the plane z = 1.
  float plane_area() const { return plane_area_; }

 private:
  FilmWindow window_;
  Vec2 principal_point_;
  float tan_x_ = 1, tan_y_ = 1, plane_area_ = 4;
};

// The parameters PerspectiveProjection reads.
std::vector<ParamSpec> perspective_projection_params();

// The tangents of the half fields of view across x and y that fov (or
// focal_length) and fov_axis give an image of w x h, as Mitsuba defines
// them; bad values are errors naming the parameter.
Vec2 field_of_view_tangents(const Properties& props, float w, float h);
// The parameters field_of_view_tangents reads.
std::vector<ParamSpec> field_of_view_params();

}  // namespace caustica
