#pragma once

#include <cmath>
#include <memory>

#include "core/errors/scene_error.h"
#include "core/lights/emitter.h"
#include "core/registry/properties.h"
#include "core/shapes/shape.h"
#include "core/texture/texture.h"
#include "core/texture/texture_parameter.h"

namespace caustica {

class Shape;

// An emitter that lights from the surface of the one shape it is nested in
// or referenced by (area, directionalarea), with its `radiance` a colour,
// a spectrum or a texture over the shape's (u, v).
class ShapeEmitter : public Emitter {
 public:
  explicit ShapeEmitter(const Properties& props)
      : radiance_(read_nonnegative_texture(props, "radiance")), where_(props.where()) {
    set_measured_emission(props.spectrum("radiance"));
  }

  void attach_shape(const Shape* shape) final {
    if (shape_) throw SceneError(where_, "an area emitter can belong to one shape only");
    shape_ = shape;
  }
  bool is_area() const final { return true; }
  // A flat shape emits into the half-space its normal faces (its normals
  // agree to 1.5e-3 radians; the cone takes 2e-3); any other, for all the
  // tree knows, in every direction.
  std::optional<LightBounds> light_bounds() const final {
    if (!shape_ || shape_->moves()) return std::nullopt;
    LightBounds b;
    b.bounds = shape_->bounds();
    b.phi = power().average();
    if (const auto n = shape_->flat_normal()) {
      b.axis = *n;
      b.cos_theta_o = std::cos(2e-3f);
      b.cos_theta_e = 0;
    }
    return b;
  }

 protected:
  std::shared_ptr<Texture> radiance_;
  const Shape* shape_ = nullptr;

 private:
  SourceLocation where_;
};

}  // namespace caustica
