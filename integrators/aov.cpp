// aov: arbitrary output variables at the first surface the camera sees,
// noise-free inputs for denoisers and compositing.
//
// Parameters
//   aovs  string  "albedo:albedo,nn:sh_normal,dd:depth"
//         comma-separated name:kind pairs; kinds are
//           albedo     the BSDF's reflectance (3 channels: name.R/G/B)
//           sh_normal  shading normal, world space (name.X/Y/Z)
//           geo_normal geometric normal, world space (name.X/Y/Z)
//           position   hit point, world space (name.X/Y/Z)
//           uv         surface coordinates (name.U/V)
//           depth      distance from the camera along the ray (name.T)
//         Rays that miss write zeros.
//
//   <integrator type="aov"><string name="aovs" value="a:albedo,n:sh_normal"/></integrator>

#include "core/bsdf/surface_bsdf.h"
#include "core/registry/properties.h"
#include "core/render/integrator.h"
#include "core/scene/scene.h"

namespace caustica {
namespace {

enum class AovKind { Albedo, ShNormal, GeoNormal, Position, Uv, Depth };

struct Aov {
  std::string name;
  AovKind kind;
};

std::vector<Aov> parse_aovs(const Properties& props) {
  const std::string text = props.get_string("aovs");
  std::vector<Aov> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    const size_t colon = item.find(':');
    if (colon == std::string::npos || colon == 0) throw props.error("aovs", "'" + item + "' is not name:kind");
    const std::string kind = item.substr(colon + 1);
    static const std::pair<const char*, AovKind> kinds[] = {{"albedo", AovKind::Albedo},
                                                            {"sh_normal", AovKind::ShNormal},
                                                            {"geo_normal", AovKind::GeoNormal},
                                                            {"position", AovKind::Position},
                                                            {"uv", AovKind::Uv},
                                                            {"depth", AovKind::Depth}};
    bool found = false;
    for (const auto& [k, v] : kinds)
      if (kind == k) {
        out.push_back({item.substr(0, colon), v});
        found = true;
      }
    if (!found)
      throw props.error("aovs",
                        "unknown kind '" + kind + "' (accepted: albedo, sh_normal, geo_normal, position, uv, depth)");
    start = end + 1;
  }
  return out;
}

class AovIntegrator final : public Integrator {
 public:
  explicit AovIntegrator(const Properties& props) : aovs_(parse_aovs(props)), text_(props.get_string("aovs")) {}

  std::vector<std::string> channels() const override {
    std::vector<std::string> out;
    for (const Aov& a : aovs_) {
      const char* suffixes = "";
      switch (a.kind) {
        case AovKind::Albedo:
          suffixes = "RGB";
          break;
        case AovKind::ShNormal:
        case AovKind::GeoNormal:
        case AovKind::Position:
          suffixes = "XYZ";
          break;
        case AovKind::Uv:
          suffixes = "UV";
          break;
        case AovKind::Depth:
          suffixes = "T";
          break;
      }
      for (const char* c = suffixes; *c; ++c) out.push_back(a.name + "." + *c);
    }
    return out;
  }

  void sample(const Scene& scene, const Ray& ray, Sampler&, std::span<float> out) const override {
    std::fill(out.begin(), out.end(), 0.0f);
    const auto si = scene.intersect(ray);
    if (!si) return;
    size_t c = 0;
    const auto put = [&](Vec3 v, int n) {
      for (int i = 0; i < n; ++i) out[c++] = v[i];
    };
    for (const Aov& a : aovs_) {
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
      }
    }
  }

  std::string describe() const override { return "aov aovs=" + text_; }

 private:
  std::vector<Aov> aovs_;
  std::string text_;
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(AovIntegrator, "integrator", "aov",
                         {{"aovs", ParamType::String, "albedo:albedo,nn:sh_normal,dd:depth", "name:kind list"}}, {});

}  // namespace caustica
