#include "integrators/radiosity/element_mesh.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/scene/embree_scene.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

float triangle_area(const std::array<Vec3, 3>& p) { return 0.5f * length(cross(p[1] - p[0], p[2] - p[0])); }

// The point with weights (w0, w1, w2), in double precision: a sum of two
// products is the same in either order, so a shared edge's points agree.
Vec3 weighted(const std::array<Vec3, 3>& v, double w0, double w1, double w2) {
  const auto at = [&](int axis) { return float(v[0][axis] * w0 + v[1][axis] * w1 + v[2][axis] * w2); };
  return {at(0), at(1), at(2)};
}

Vec2 weighted(const std::array<Vec2, 3>& v, double w0, double w1, double w2) {
  return {float(v[0].x * w0 + v[1].x * w1 + v[2].x * w2), float(v[0].y * w0 + v[1].y * w1 + v[2].y * w2)};
}

Element make_element(const std::array<Vec3, 3>& p, const std::array<Vec2, 3>& uv, uint32_t surface, int level) {
  Element e;
  e.p = p;
  e.uv = uv;
  e.surface = surface;
  e.level = level;
  e.area = triangle_area(p);
  return e;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

float Element::longest_edge() const {
  return std::max({length(p[1] - p[0]), length(p[2] - p[1]), length(p[0] - p[2])});
}

std::vector<Element> uniform_elements(const std::vector<SurfaceTriangle>& surfaces, float edge) {
  std::vector<Element> elements;
  for (uint32_t s = 0; s < surfaces.size(); ++s) {
    const SurfaceTriangle& t = surfaces[s];
    const float longest = std::max({length(t.p[1] - t.p[0]), length(t.p[2] - t.p[1]), length(t.p[0] - t.p[2])});
    const int n = std::max(1, int(std::ceil(longest / edge)));
    const auto corner = [&](int i, int j) {
      const double w1 = double(i) / n, w2 = double(j) / n, w0 = double(n - i - j) / n;
      return std::pair{weighted(t.p, w0, w1, w2), weighted(t.uv, w0, w1, w2)};
    };
    const auto add = [&](std::pair<Vec3, Vec2> a, std::pair<Vec3, Vec2> b, std::pair<Vec3, Vec2> c) {
      Element e = make_element({a.first, b.first, c.first}, {a.second, b.second, c.second}, s, 0);
      if (e.area > 0) elements.push_back(e);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        add(corner(i, j), corner(i + 1, j), corner(i, j + 1));
        if (i + j + 2 <= n) add(corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1));
      }
  }
  return elements;
}

std::array<Element, 4> split(const Element& e) {
  const auto mid = [&](double w0, double w1, double w2) {
    return std::pair{weighted(e.p, w0, w1, w2), weighted(e.uv, w0, w1, w2)};
  };
  const auto m01 = mid(0.5, 0.5, 0), m12 = mid(0, 0.5, 0.5), m20 = mid(0.5, 0, 0.5);
  const int level = e.level + 1;
  return {make_element({e.p[0], m01.first, m20.first}, {e.uv[0], m01.second, m20.second}, e.surface, level),
          make_element({m01.first, e.p[1], m12.first}, {m01.second, e.uv[1], m12.second}, e.surface, level),
          make_element({m20.first, m12.first, e.p[2]}, {m20.second, m12.second, e.uv[2]}, e.surface, level),
          make_element({m01.first, m12.first, m20.first}, {m01.second, m12.second, m20.second}, e.surface, level)};
}

std::pair<int, Vec2> child_at(Vec2 b) {
  const float b0 = 1 - b.x - b.y;
  if (b0 >= 0.5f) return {0, {2 * b.x, 2 * b.y}};
  if (b.x >= 0.5f) return {1, {2 * b.x - 1, 2 * b.y}};
  if (b.y >= 0.5f) return {2, {2 * b.x, 2 * b.y - 1}};
  return {3, {1 - 2 * b0, 1 - 2 * b.x}};
}

ElementScene::ElementScene(std::span<const Element> elements) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("cannot create an Embree device for the radiosity mesh");
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  if (!elements.empty()) attach(elements);
  rtcCommitScene(scene_);
  if (const RTCError error = rtcGetDeviceError(device_); error != RTC_ERROR_NONE)
    throw std::runtime_error("Embree failed to build the radiosity mesh (error " + std::to_string(int(error)) + ")");
}

void ElementScene::attach(std::span<const Element> elements) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), 3 * elements.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), elements.size()));
  for (size_t i = 0; i < elements.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      for (int axis = 0; axis < 3; ++axis) vertices[9 * i + 3 * k + axis] = elements[i].p[k][axis];
      indices[3 * i + k] = unsigned(3 * i + k);
    }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
}

ElementScene::~ElementScene() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

bool ElementScene::visible(Vec3 from, Vec3 to) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = to_rtc(Ray{from, to - from, 1.0f});
  rtcOccluded1(scene_, &context, &r);
  return r.tfar >= 0;
}

std::optional<ElementScene::Hit> ElementScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayhit{};
  rayhit.ray = to_rtc(ray);
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayhit);
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return Hit{rayhit.hit.primID, {rayhit.hit.u, rayhit.hit.v}, rayhit.ray.tfar};
}

}  // namespace caustica
