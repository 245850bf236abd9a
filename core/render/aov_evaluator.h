#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/geometry/interaction.h"
#include "core/geometry/ray.h"

namespace caustica {
class Scene;
}

namespace caustica {

enum class AovKind {
  Albedo,
  ShNormal,
  GeoNormal,
  Position,
  Uv,
  Depth,
  Coverage,
  DpDu,
  DpDv,
  DuvDx,
  DuvDy,
  PrimIndex,
  ShapeIndex,
  BoundaryTest
};

struct AovSpec {
  std::string name;
  AovKind kind;
};

// Parses "name:kind,name:kind" (kinds: albedo, sh_normal, geo_normal,
// position, uv, depth, coverage, dp_du, dp_dv, duv_dx, duv_dy, prim_index,
// shape_index, boundary_test);
// throws std::invalid_argument naming the bad item.
std::vector<AovSpec> parse_aov_list(const std::string& text);

// Values at the first surface a ray meets: noise-free inputs for denoisers
// and compositing. Misses write zeros.
class AovEvaluator {
 public:
  explicit AovEvaluator(std::vector<AovSpec> aovs) : aovs_(std::move(aovs)) {}

  // Channel names: name.R/G/B, name.X/Y/Z, name.U/V, name.T (depth),
  // name.A (coverage: 1 where the ray meets a surface, an alpha channel) or
  // name.I (an index); without a name, only the suffix ("A");
  // boundary_test's channel is the name alone, as in Mitsuba 3.
  std::vector<std::string> channels() const;
  // The values at `hit`, the first surface `ray` meets (none: zeros, and
  // 1 for boundary_test, as in Mitsuba 3). duv_dx and duv_dy, the change of
  // (u, v) from one pixel to the next along x and y, need the `scene` whose
  // sensor made the ray (without one, or where the neighbouring rays miss
  // the hit's tangent plane: zeros); boundary_test needs its shapes.
  void evaluate(const Ray& ray, const std::optional<SurfaceInteraction>& hit, std::span<float> out,
                const Scene* scene = nullptr) const;

 private:
  std::vector<AovSpec> aovs_;
};

}  // namespace caustica
