#pragma once

#include "integrators/radiosity/element_mesh.h"

namespace caustica {

// One side of an element: its corners and the unit normal of the side.
struct ElementSide {
  const Element* element;
  Vec3 n;
};

// The form factor F from one element side to another: the mean over
// quadrature points x of `from` of the exact point-to-triangle form factor
// toward `to` (zero where x lies behind `to`), times the fraction of
// `visibility_rays` segments between points of the two that `scene` leaves
// unblocked (none cast where scene is null). Elements close to each other
// for their size take 16 quadrature points, others 4. `offset` lifts the
// segments' ends off their surfaces along the normals.
float element_form_factor(const ElementSide& from, const ElementSide& to, const ElementScene* scene,
                          int visibility_rays, float offset);

}  // namespace caustica
