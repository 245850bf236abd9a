#include "core/render/aov_evaluator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/bsdf/surface_bsdf.h"
#include "core/camera/sensor.h"
#include "core/scene/scene.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

const std::pair<const char*, AovKind> kKinds[] = {{"albedo", AovKind::Albedo},
                                                  {"sh_normal", AovKind::ShNormal},
                                                  {"geo_normal", AovKind::GeoNormal},
                                                  {"position", AovKind::Position},
                                                  {"uv", AovKind::Uv},
                                                  {"depth", AovKind::Depth},
                                                  {"coverage", AovKind::Coverage},
                                                  {"dp_du", AovKind::DpDu},
                                                  {"dp_dv", AovKind::DpDv},
                                                  {"duv_dx", AovKind::DuvDx},
                                                  {"duv_dy", AovKind::DuvDy},
                                                  {"prim_index", AovKind::PrimIndex},
                                                  {"shape_index", AovKind::ShapeIndex},
                                                  {"boundary_test", AovKind::BoundaryTest}};

const char* suffixes(AovKind kind) {
  switch (kind) {
    case AovKind::Albedo:
      return "RGB";
    case AovKind::ShNormal:
    case AovKind::GeoNormal:
    case AovKind::Position:
    case AovKind::DpDu:
    case AovKind::DpDv:
      return "XYZ";
    case AovKind::PrimIndex:
    case AovKind::ShapeIndex:
      return "I";
    case AovKind::Uv:
    case AovKind::DuvDx:
    case AovKind::DuvDy:
      return "UV";
    case AovKind::Depth:
      return "T";
    case AovKind::Coverage:
      return "A";
    case AovKind::BoundaryTest:
      return "";
  }
  return "";
}

// How many channels a kind writes: one per suffix, boundary_test's one
// named by the aov alone.
size_t width(AovKind kind) {
  return kind == AovKind::BoundaryTest ? 1 : std::char_traits<char>::length(suffixes(kind));
}

// d(u, v) between the pixel `ray` leaves through and its neighbour one
// pixel along `step`: the neighbour's ray (through the lens centre) meets
// the hit's tangent plane at p + dp, and dp = dp/du du + dp/dv dv is solved
// for (du, dv) by least squares. Zero where no neighbour ray meets the plane.
Vec2 uv_step(const Sensor& sensor, const Ray& ray, const SurfaceInteraction& si, Vec2 step) {
  Vec2 raster;
  if (sensor.We(ray, &raster).is_black()) return {};
  const Ray next = sensor.generate_ray(raster + step, {0.5f, 0.5f}, ray.time);
  const float facing = dot(si.ng, next.d);
  if (!(std::abs(facing) > 1e-8f)) return {};
  const float t = dot(si.ng, si.p - next.o) / facing;
  if (!(t > 0)) return {};
  const Vec3 dp = next.o + next.d * t - si.p;
  const double a = dot(si.dpdu, si.dpdu), b = dot(si.dpdu, si.dpdv), c = dot(si.dpdv, si.dpdv);
  const double det = a * c - b * b;
  if (!(std::abs(det) > 0)) return {};
  const double pu = dot(si.dpdu, dp), pv = dot(si.dpdv, dp);
  return {float((c * pu - b * pv) / det), float((a * pv - b * pu) / det)};
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::vector<AovSpec> parse_aov_list(const std::string& text) {
  std::vector<AovSpec> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    const size_t colon = item.find(':');
    if (colon == std::string::npos || colon == 0) throw std::invalid_argument("'" + item + "' is not name:kind");
    const std::string kind = item.substr(colon + 1);
    const auto it = std::find_if(std::begin(kKinds), std::end(kKinds), [&](const auto& k) { return kind == k.first; });
    if (it == std::end(kKinds))
      throw std::invalid_argument("unknown kind '" + kind +
                                  "' (accepted: albedo, sh_normal, geo_normal, position, uv, depth, coverage, "
                                  "dp_du, dp_dv, duv_dx, duv_dy, prim_index, shape_index, boundary_test)");
    out.push_back({item.substr(0, colon), it->second});
    start = end + 1;
  }
  return out;
}

std::vector<std::string> AovEvaluator::channels() const {
  std::vector<std::string> out;
  for (const AovSpec& a : aovs_) {
    if (a.kind == AovKind::BoundaryTest) out.push_back(a.name.empty() ? "B" : a.name);
    for (const char* c = suffixes(a.kind); *c; ++c)
      out.push_back(a.name.empty() ? std::string(1, *c) : a.name + "." + *c);
  }
  return out;
}

void AovEvaluator::evaluate(const Ray& ray, const std::optional<SurfaceInteraction>& si, std::span<float> out,
                            const Scene* scene) const {
  std::fill(out.begin(), out.end(), 0.0f);
  if (!si) {
    size_t c = 0;
    for (const AovSpec& a : aovs_) {
      if (a.kind == AovKind::BoundaryTest) out[c] = 1;
      c += width(a.kind);
    }
    return;
  }
  size_t c = 0;
  const auto put = [&](Vec3 v, int n) {
    for (int i = 0; i < n; ++i) out[c++] = v[i];
  };
  for (const AovSpec& a : aovs_) {
    switch (a.kind) {
      case AovKind::Albedo: {
        const Color albedo = SurfaceBsdf(*si->shape->bsdf(), *si, TransportMode::Radiance).albedo(-ray.d);
        put({albedo.r, albedo.g, albedo.b}, 3);
        break;
      }
      case AovKind::ShNormal:
        put(si->shading.n, 3);
        break;
      case AovKind::GeoNormal:
        put(si->ng, 3);
        break;
      case AovKind::Position:
        put(si->p, 3);
        break;
      case AovKind::Uv:
        put({si->uv.x, si->uv.y, 0}, 2);
        break;
      case AovKind::Depth:
        put({si->t, 0, 0}, 1);
        break;
      case AovKind::Coverage:
        put({1, 0, 0}, 1);
        break;
      case AovKind::DpDu:
        put(si->dpdu, 3);
        break;
      case AovKind::DpDv:
        put(si->dpdv, 3);
        break;
      case AovKind::DuvDx:
      case AovKind::DuvDy: {
        const Vec2 d =
            scene ? uv_step(scene->sensor(), ray, *si, a.kind == AovKind::DuvDx ? Vec2(1, 0) : Vec2(0, 1)) : Vec2();
        put({d.x, d.y, 0}, 2);
        break;
      }
      // Exact as floats up to 2^24.
      case AovKind::PrimIndex:
        put({float(si->prim), 0, 0}, 1);
        break;
      case AovKind::ShapeIndex:
        put({float(si->shape_index), 0, 0}, 1);
        break;
      // The shape the ray met at the top of the scene (an instance or a
      // moving shape, not its group's or still shape) places the test.
      case AovKind::BoundaryTest:
        put({scene ? scene->accel().shape(si->shape_index).boundary_test(*si, normalize(ray.d)) : 1, 0, 0}, 1);
        break;
    }
  }
}

}  // namespace caustica
