#pragma once

#include <memory>
#include <string>

#include "core/geometry/bounds.h"
#include "core/math/color.h"
#include "core/registry/plugin.h"

namespace caustica {

class Properties;

// A quantity that varies through space (a medium's extinction or albedo):
// a value per channel at every point of render space, zero outside the
// volume's box.
class Volume : public Plugin {
 public:
  virtual Color eval(Vec3 p) const = 0;
  // The same value everywhere (then max_in is that value).
  virtual bool is_constant() const = 0;
  // Its channels may differ.
  virtual bool is_chromatic() const = 0;
  // An upper bound of every channel's value over the part of the volume
  // whose local coordinates (local()) lie in `cell`, a box within [0, 1]^3.
  virtual float max_in(const Bounds3& cell) const = 0;
  // The point p in the volume's own coordinates, where [0, 1]^3 is its box.
  virtual Vec3 local(Vec3 p) const = 0;
  virtual Vec3 local_vector(Vec3 v) const = 0;
  // The resolution of its data along each axis (1 for a constant).
  virtual Vec3 resolution() const { return {1, 1, 1}; }
};

// Parameter `name` of a medium as a volume: a nested <volume>, or a
// number or colour, which is then the same everywhere.
std::shared_ptr<const Volume> read_volume(const Properties& props, const std::string& name);

}  // namespace caustica
