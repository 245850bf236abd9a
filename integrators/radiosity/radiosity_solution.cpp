#include "integrators/radiosity/radiosity_solution.h"

#include <tbb/parallel_for.h>

#include <bit>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "core/bsdf/bsdf.h"
#include "core/lights/emitter.h"
#include "core/math/frame.h"
#include "core/sampling/warp.h"
#include "core/scene/scene.h"
#include "integrators/radiosity/element_form_factor.h"
#include "integrators/radiosity/form_factor.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kMaxSweeps = 10000;

float max_channel(Color c) { return std::max({c.r, c.g, c.b}); }

Vec2 uv_at(const Element& e, Vec2 b) { return e.uv[0] * (1 - b.x - b.y) + e.uv[1] * b.x + e.uv[2] * b.y; }

Color reflectance(const Shape& shape, Vec2 uv, float side) {
  BsdfContext ctx;
  ctx.uv = uv;
  return shape.bsdf()->albedo(ctx, {0, 0, side});
}

Color emission(const Shape& shape, Vec3 p, Vec3 ng, Vec2 uv, Vec3 w) {
  if (!shape.emitter()) return {};
  SurfaceInteraction si;
  si.p = p;
  si.ng = ng;
  si.shading = Frame::from_normal(ng);
  si.uv = uv;
  si.shape = &shape;
  return shape.emitter()->L(si, w);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

RadiositySolution::RadiositySolution(const Scene& scene, const RadiositySettings& settings)
    : scene_(scene), settings_(settings) {
  surfaces_ = surface_triangles(scene, settings.patch_size);
  Bounds3 bounds;
  for (const SurfaceTriangle& t : surfaces_)
    for (const Vec3& p : t.p) bounds.expand(p);
  offset_ = bounds.empty() ? 0 : 1e-5f * length(bounds.hi - bounds.lo);
  elements_ = uniform_elements(surfaces_, settings.patch_size);
  roots_ = elements_.size();
  accel_ = std::make_unique<ElementScene>(std::span(elements_).first(roots_));
  for (stats_.levels = 0;; ++stats_.levels) {
    build_unknowns();
    solve(form_factors());
    average_corners();
    if (stats_.levels == settings_.refinements || !refine()) break;
  }
  stats_.elements = 0;
  for (const Element& e : elements_) stats_.elements += e.children < 0;
  stats_.unknowns = unknowns_.size();
}

RadiositySolution::~RadiositySolution() = default;

void RadiositySolution::build_unknowns() {
  unknowns_.clear();
  side_unknown_.assign(elements_.size(), {-1, -1});
  const std::vector<Vec2> points = subtriangle_centroids(2);
  for (uint32_t e = 0; e < elements_.size(); ++e) {
    const Element& element = elements_[e];
    if (element.children >= 0) continue;
    const SurfaceTriangle& surface = surfaces_[element.surface];
    for (int s = 0; s < 2; ++s) {
      const float side = s == 0 ? 1.0f : -1.0f;
      Unknown u{e, surface.n * side, {}, {}, {}, {}};
      for (const Vec2 b : points) {
        const Vec2 uv = uv_at(element, b);
        const Vec3 p = element.p[0] * (1 - b.x - b.y) + element.p[1] * b.x + element.p[2] * b.y;
        u.rho += reflectance(*surface.shape, uv, side) / float(points.size());
        u.emitted += emission(*surface.shape, p, surface.n, uv, u.n) / float(points.size());
      }
      if (max_channel(u.rho) <= 0 && max_channel(u.emitted) <= 0) continue;
      u.L = u.emitted;
      side_unknown_[e][s] = int32_t(unknowns_.size());
      unknowns_.push_back(u);
    }
  }
}

std::vector<RadiositySolution::Row> RadiositySolution::form_factors() const {
  std::vector<Row> rows(unknowns_.size());
  tbb::parallel_for(size_t(0), unknowns_.size(), [&](size_t i) {
    const Unknown& from = unknowns_[i];
    if (max_channel(from.rho) <= 0) return;
    for (uint32_t j = 0; j < unknowns_.size(); ++j) {
      const Unknown& to = unknowns_[j];
      if (to.element == from.element) continue;
      const float F = element_form_factor({&elements_[from.element], from.n}, {&elements_[to.element], to.n},
                                          accel_.get(), settings_.visibility_rays, offset_);
      if (F > 0) rows[i].emplace_back(j, F);
    }
  });
  return rows;
}

void RadiositySolution::solve(const std::vector<Row>& rows) {
  const auto gathered = [&](size_t i) {
    Color sum;
    for (const auto& [j, F] : rows[i]) sum += unknowns_[j].L * F;
    return unknowns_[i].emitted + unknowns_[i].rho * sum;
  };
  stats_.form_factors = 0;
  for (const Row& row : rows) stats_.form_factors += row.size();
  for (stats_.sweeps = 1; stats_.sweeps <= kMaxSweeps; ++stats_.sweeps) {
    for (size_t i = 0; i < unknowns_.size(); ++i) unknowns_[i].L = gathered(i);
    float largest = 0, change = 0;
    for (size_t i = 0; i < unknowns_.size(); ++i) {
      largest = std::max(largest, max_channel(unknowns_[i].L));
      const Color d = gathered(i) - unknowns_[i].L;
      change = std::max({change, std::abs(d.r), std::abs(d.g), std::abs(d.b)});
    }
    stats_.residual = largest > 0 ? change / largest : 0;
    if (stats_.residual <= settings_.tolerance) return;
  }
  throw std::runtime_error("radiosity: the linear system did not converge in " + std::to_string(kMaxSweeps) +
                           " sweeps (residual " + std::to_string(stats_.residual) +
                           "); is a reflectance 1 or more in a closed scene?");
}

void RadiositySolution::average_corners() {
  // Corners meet where their positions are bitwise equal, on one shape.
  std::map<std::tuple<const Shape*, uint32_t, uint32_t, uint32_t>, std::vector<uint32_t>> meeting;
  const auto key = [&](const Unknown& u, int k) {
    const Vec3 p = elements_[u.element].p[k];
    return std::tuple{surfaces_[elements_[u.element].surface].shape, std::bit_cast<uint32_t>(p.x),
                      std::bit_cast<uint32_t>(p.y), std::bit_cast<uint32_t>(p.z)};
  };
  for (uint32_t i = 0; i < unknowns_.size(); ++i)
    for (int k = 0; k < 3; ++k) meeting[key(unknowns_[i], k)].push_back(i);
  for (Unknown& u : unknowns_)
    for (int k = 0; k < 3; ++k) {
      Color sum;
      float area = 0;
      for (const uint32_t j : meeting[key(u, k)]) {
        const Unknown& other = unknowns_[j];
        if (dot(other.n, u.n) < 0.9f) continue;
        sum += other.L * elements_[other.element].area;
        area += elements_[other.element].area;
      }
      u.corner[k] = sum / area;
    }
}

bool RadiositySolution::refine() {
  double reflected = 0, area = 0;
  for (const Unknown& u : unknowns_) {
    reflected += double((u.L - u.emitted).luminance()) * elements_[u.element].area;
    area += elements_[u.element].area;
  }
  const float threshold = settings_.refine_threshold * float(reflected / area);
  std::vector<uint32_t> to_split;
  for (const Unknown& u : unknowns_)
    for (const Color& c : u.corner)
      if (std::abs(c.luminance() - u.L.luminance()) > threshold && (to_split.empty() || to_split.back() != u.element))
        to_split.push_back(u.element);
  for (const uint32_t e : to_split) {
    elements_[e].children = int32_t(elements_.size());
    for (const Element& child : split(elements_[e])) elements_.push_back(child);
  }
  return !to_split.empty();
}

std::optional<RadiositySolution::SideHit> RadiositySolution::side_hit(const Ray& ray) const {
  auto hit = accel_->intersect(ray);
  if (!hit) return std::nullopt;
  while (elements_[hit->element].children >= 0) {
    const auto [child, b] = child_at(hit->b);
    hit->element = uint32_t(elements_[hit->element].children + child);
    hit->b = b;
  }
  const Vec3 n = surfaces_[elements_[hit->element].surface].n;
  const int32_t index = side_unknown_[hit->element][dot(ray.d, n) < 0 ? 0 : 1];
  return SideHit{index < 0 ? nullptr : &unknowns_[size_t(index)], *hit};
}

Color RadiositySolution::interpolated(const Ray& ray) const {
  const auto h = side_hit(ray);
  if (!h || !h->unknown) return {};
  const Vec2 b = h->hit.b;
  return h->unknown->corner[0] * (1 - b.x - b.y) + h->unknown->corner[1] * b.x + h->unknown->corner[2] * b.y;
}

Color RadiositySolution::gathered(const Ray& ray, Sampler& sampler, int rays) const {
  const auto h = side_hit(ray);
  if (!h || !h->unknown) return {};
  const Unknown& u = *h->unknown;
  const Element& element = elements_[u.element];
  const Vec3 p = ray.o + ray.d * h->hit.t + u.n * offset_;
  const Frame frame = Frame::from_normal(u.n);
  Color incident;
  for (int i = 0; i < rays; ++i)
    incident += interpolated(Ray{p, frame.to_world(square_to_cosine_hemisphere(sampler.next_2d()))});
  const float side = dot(u.n, surfaces_[element.surface].n) > 0 ? 1.0f : -1.0f;
  const Color rho = reflectance(*surfaces_[element.surface].shape, uv_at(element, h->hit.b), side);
  return u.emitted + rho * incident / float(rays);
}

}  // namespace caustica
