#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/math/color.h"
#include "core/sampling/sampler.h"
#include "integrators/radiosity/element_mesh.h"

namespace caustica {

class Scene;

struct RadiositySettings {
  float patch_size = 0;  // element edge length before adaptive splitting
  int refinements = 2;   // levels of adaptive splitting
  // An element is split where the radiance at its corners differs from its
  // own by more than this times the mean reflected radiance.
  float refine_threshold = 0.25f;
  int visibility_rays = 4;  // per pair of elements
  double tolerance = 1e-4;  // residual of the linear system, relative to the largest radiance
};

// What the solution took, for the render's summary.
struct RadiosityStats {
  size_t elements = 0, unknowns = 0, form_factors = 0;
  int levels = 0, sweeps = 0;
  double residual = 0;
};

// The radiance leaving every element of a diffuse scene: the system
// L_i = E_i + rho_i sum_j F_ij L_j over element sides (one unknown per side
// that reflects or emits), F from element_form_factor with visibility,
// solved by Gauss-Seidel sweeps to the tolerance; then solved again after
// splitting the elements where L varies, `refinements` times. Deterministic:
// the same for any thread count.
class RadiositySolution {
 public:
  RadiositySolution(const Scene& scene, const RadiositySettings& settings);
  ~RadiositySolution();

  // Radiance leaving the first element `ray` meets back along the ray,
  // interpolated between the values at its corners (which average the
  // elements of the same surface meeting there); zero if it meets none.
  Color interpolated(const Ray& ray) const;
  // The same point's radiance by one bounce of final gathering: its
  // emission plus its reflectance there times the mean interpolated
  // radiance `rays` cosine-distributed rays meet.
  Color gathered(const Ray& ray, Sampler& sampler, int rays) const;
  const RadiosityStats& stats() const { return stats_; }

 private:
  struct Unknown {
    uint32_t element;
    Vec3 n;
    Color rho, emitted, L;
    std::array<Color, 3> corner;
  };
  using Row = std::vector<std::pair<uint32_t, float>>;

  void build_unknowns();
  std::vector<Row> form_factors() const;
  void solve(const std::vector<Row>& rows);
  void average_corners();
  bool refine();
  // The element side `ray` meets first, with the barycentrics of the hit.
  struct SideHit {
    const Unknown* unknown;
    ElementScene::Hit hit;
  };
  std::optional<SideHit> side_hit(const Ray& ray) const;

  const Scene& scene_;
  RadiositySettings settings_;
  std::vector<SurfaceTriangle> surfaces_;
  std::vector<Element> elements_;  // the unsplit ones first, then children as they are split
  size_t roots_ = 0;
  std::vector<Unknown> unknowns_;
  std::vector<std::array<int32_t, 2>> side_unknown_;  // per element: front, back (-1: black)
  std::unique_ptr<ElementScene> accel_;
  float offset_ = 0;
  RadiosityStats stats_;
};

}  // namespace caustica
