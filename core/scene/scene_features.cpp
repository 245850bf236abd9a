#include "core/scene/scene_features.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/bsdf/bsdf.h"
#include "core/media/medium.h"
#include "core/scene/scene.h"
#include "core/spectral/rgb_lift.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

constexpr int kProbePoints = 256;

// A low-discrepancy point set (the R2 sequence): the probes cover a
// surface evenly without a random number generator.
Vec2 r2_point(int i) {
  constexpr double g = 1.32471795724474602596;  // the plastic number
  const double x = 0.5 + (i + 1) / g, y = 0.5 + (i + 1) / (g * g);
  return {float(x - std::floor(x)), float(y - std::floor(y))};
}

// Whether any light shines directly on some point of `shape`; null
// surfaces (which may bound media: light is dimmed there, not stopped) are
// looked through.
bool lit_directly(const Scene& scene, const Shape& shape) {
  for (int i = 0; i < kProbePoints; ++i) {
    const PositionSample ps = shape.sample_position(r2_point(i));
    if (!(ps.pdf > 0)) continue;
    SurfaceInteraction si;
    si.p = ps.p;
    si.p_error = ps.p_error;
    si.ng = ps.n;
    for (const auto& emitter : scene.emitters()) {
      const auto ls = emitter->sample_Li({ps.p, ps.p_error, ps.n}, r2_point(i + kProbePoints));
      if (!ls || !(ls->pdf > 0) || ls->Li.is_black()) continue;
      const Ray shadow = ls->is_infinite ? si.spawn(ls->wi) : si.spawn_to(ls->p, ls->p_error, ls->n);
      if (!scene.intersect_shown(shadow)) return true;
    }
  }
  return false;
}

// The surfaces rays leaving the lights meet first: a narrow beam (a spot
// light's cone) lights so little of a surface that probes spread over it
// may all miss it.
std::set<const Shape*> met_by_light_rays(const Scene& scene) {
  std::set<const Shape*> met;
  for (const auto& emitter : scene.emitters())
    for (int i = 0; i < kProbePoints; ++i) {
      const auto le = emitter->sample_Le(r2_point(i), r2_point(i + kProbePoints));
      if (!le || le->Le.is_black()) continue;
      if (const auto si = scene.intersect_shown(le->ray)) met.insert(si->shape);
    }
  return met;
}

std::string lobe_names(uint32_t lobes) {
  std::string out;
  const std::pair<uint32_t, const char*> names[] = {
      {kDiffuseReflection, "diffuse reflection"}, {kDiffuseTransmission, "diffuse transmission"},
      {kGlossyReflection, "glossy reflection"},   {kGlossyTransmission, "glossy transmission"},
      {kDeltaReflection, "delta reflection"},     {kDeltaTransmission, "delta transmission"},
      {kNull, "null (index-matched boundaries)"}};
  for (const auto& [flag, name] : names)
    if (lobes & flag) {
      if (!out.empty()) out += ", ";
      out += name;
    }
  return out.empty() ? "none" : out;
}

void count_media(const Scene& scene, SceneFeatures& f) {
  std::set<const Medium*> media;
  // A moving shape's hits name the still shape it carries, which bounds the media.
  for (const auto& shape : scene.shapes())
    for (const Shape* s : shape->material_surfaces()) {
      if (s->interior()) media.insert(s->interior());
      if (s->exterior()) media.insert(s->exterior());
    }
  if (const Medium* camera = scene.sensor().medium()) {
    media.insert(camera);
    f.camera_in_medium = true;
  }
  for (const Medium* m : media) {
    f.heterogeneous_media += !m->is_homogeneous();
    f.chromatic_media += m->is_chromatic();
  }
  f.media = int(media.size());
  f.medium_walk = f.media > 0 || (f.lobes & kNull);
}

constexpr const char* kNothingCallsForSpectral =
    "nothing in the scene needs it: no dispersive dielectric, spectral emitter or measured conductor";

// Why the scene calls for spectral transport, or "".
std::string spectral_content(const Scene& scene, const std::vector<GivenSpectrum>& spectra) {
  for (const auto& shape : scene.shapes())
    for (const Shape* s : shape->material_surfaces())
      if (s->bsdf() && s->bsdf()->disperses()) return "a dispersive dielectric: " + s->kind();
  for (const GivenSpectrum& g : spectra) {
    const std::string given = g.where.str() + ": " + g.owner + " " + g.parameter + " given as a spectrum";
    if (g.owner == "bsdf" && (g.parameter == "eta" || g.parameter == "k"))
      return "a conductor whose index is measured: " + given;
    // Spectral transport reads the spectra given to materials and emitters
    // (not those inside textures, media or the like, which stay colours).
    if (g.owner != "bsdf" && g.owner != "emitter") continue;
    const double misfit = lift_misfit(*g.spectrum, g.owner == "emitter");
    if (misfit > kSpectrumMisfitThreshold) {
      char percent[16];
      std::snprintf(percent, sizeof percent, "%.0f%%", 100 * misfit);
      return given + " that RGB would misrepresent (" + percent + " away from its colour's smooth spectrum)";
    }
  }
  return "";
}

void decide_spectral(const Scene& scene, const std::vector<GivenSpectrum>& spectra, SceneFeatures& f) {
  const std::string content = spectral_content(scene, spectra);
  if (content.empty()) {
    f.spectral_reason = kNothingCallsForSpectral;
  } else if (f.medium_walk) {
    f.spectral_reason = "the scene holds " + content +
                        ", but its media are not rendered spectrally yet (nor index-matched null boundaries)";
  } else {
    f.spectral = true;
    f.spectral_reason = content;
  }
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

SceneFeatures analyze_scene(const Scene& scene, bool textures, const std::vector<GivenSpectrum>& spectra) {
  SceneFeatures f;
  f.textures = textures;
  f.camera = scene.sensor().plugin_name();
  f.pinhole = !scene.sensor().has_lens();
  for (const auto& e : scene.emitters()) {
    f.area_lights += e->is_area();
    f.point_lights += e->is_delta() && !e->is_infinite();
    f.directional_lights += e->is_delta() && e->is_infinite();
    f.environment_lights += e->is_environment();
    f.moving_lights += e->moves();
    f.light_path_only_lights += e->seen_by_light_paths_only();
  }
  bool receiver = false;
  for (const auto& s : scene.shapes()) {
    f.moving_shapes += s->moves();
    f.lobes |= s->lobes();
    receiver = receiver || (s->lobes() & ~(kDelta | kNull));
  }
  f.moving_camera = scene.sensor().moves();
  f.motion = f.moving_shapes > 0 || f.moving_lights > 0 || f.moving_camera;
  int specular_shapes = 0;
  const Shape* lit_specular = nullptr;
  const std::set<const Shape*> met = met_by_light_rays(scene);
  for (const auto& s : scene.shapes()) {
    if (!(s->lobes() & kDelta)) continue;
    ++specular_shapes;
    // A hit names the operand of a csg solid, and its points are what the
    // probes sample.
    for (const Shape* surface : s->material_surfaces())
      if (!lit_specular && (surface->lobes() & kDelta) && (met.count(surface) || lit_directly(scene, *surface)))
        lit_specular = surface;
  }
  if (specular_shapes == 0) {
    f.caustics_reason = "no surface has a delta lobe (mirror or smooth glass)";
  } else if (!lit_specular) {
    f.caustics_reason = "no light reaches any of the " + std::to_string(specular_shapes) + " delta surfaces";
  } else if (!receiver) {
    f.caustics_reason = "no surface has a non-delta lobe to receive them";
  } else {
    f.caustic_paths = true;
    f.caustics_reason = "a light reaches a surface with a delta lobe: " + lit_specular->kind();
  }
  count_media(scene, f);
  std::set<std::string> rgb_only;
  for (const auto& shape : scene.shapes())
    for (const Shape* s : shape->material_surfaces())
      if (s->bsdf() && !s->bsdf()->renders_spectral()) rgb_only.insert(s->bsdf()->plugin_name());
  f.rgb_only_materials.assign(rgb_only.begin(), rgb_only.end());
  decide_spectral(scene, spectra, f);
  const size_t tree_lights = scene.light_selection().tree_lights();
  f.light_tree = tree_lights >= 2;
  f.light_selection_reason = f.light_tree ? std::to_string(tree_lights) + " emitters it can bound"
                                          : "fewer than two emitters a light tree could bound, so the choice would "
                                            "not depend on the point";
  return f;
}

void force_light_tree(SceneFeatures& f, bool tree, const std::string& why) {
  f.light_tree = tree;
  f.light_selection_reason = why;
}

void force_spectral(SceneFeatures& f, bool spectral, const std::string& why) {
  f.spectral = spectral;
  f.spectral_reason = why;
}

std::string describe(const SceneFeatures& f) {
  std::ostringstream out;
  out << "bsdf lobes: " << lobe_names(f.lobes) << "\nlights: " << f.area_lights << " area, " << f.point_lights
      << " point, " << f.directional_lights << " directional, " << f.environment_lights
      << " environment\ntextures: " << (f.textures ? "yes" : "no") << "\ncamera: " << f.camera
      << (f.pinhole ? " (no lens to sample)" : " (a lens to sample)")
      << "\ncaustic paths: " << (f.caustic_paths ? "possible (" : "impossible (") << f.caustics_reason << ")\n";
  out << "media: ";
  if (f.media == 0) {
    out << "none";
  } else {
    out << f.media << " (" << f.media - f.heterogeneous_media << " homogeneous, " << f.heterogeneous_media
        << " heterogeneous; " << f.chromatic_media << " with extinction differing between channels)";
    if (f.camera_in_medium) out << "; the camera sits in one";
  }
  out << "\nmotion: ";
  if (f.motion) {
    const auto count = [](int n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); };
    std::vector<std::string> what;
    if (f.moving_shapes > 0) what.push_back(count(f.moving_shapes, "shape"));
    if (f.moving_lights > 0) what.push_back(count(f.moving_lights, "light"));
    if (f.moving_camera) what.push_back("the camera");
    out << "moving during the shutter: ";
    for (size_t i = 0; i < what.size(); ++i) out << (i == 0 ? "" : i + 1 == what.size() ? " and " : ", ") << what[i];
    out << "; camera rays draw a time";
  } else {
    out << "none (nothing moves; no time is drawn)";
  }
  out << "\n"
      << describe_transport(f) << "\nlight selection: " << (f.light_tree ? "light tree (" : "by power (")
      << f.light_selection_reason << ")\n";
  return out.str();
}

std::string describe_transport(const SceneFeatures& f) {
  return std::string("spectral transport: ") + (f.spectral ? "yes (" : "no, RGB (") + f.spectral_reason + ")";
}

bool transport_worth_telling(const SceneFeatures& f) {
  return f.spectral || f.spectral_reason != kNothingCallsForSpectral;
}

}  // namespace caustica
