#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/errors/scene_error.h"
#include "core/math/sampled_spectrum.h"

namespace caustica {

class Scene;

// What a scene calls for, summarised once at load, so that integrators do
// only the work the scene can use and say what they skip.
struct SceneFeatures {
  uint32_t lobes = 0;  // BsdfLobe flags of every surface together
  int area_lights = 0, point_lights = 0, directional_lights = 0, environment_lights = 0;
  // Lights only paths traced from the lights can see (directionalarea).
  int light_path_only_lights = 0;
  bool textures = false;
  std::string camera;   // the sensor's plugin name
  bool pinhole = true;  // no lens to sample
  // Caustic paths (light focused through mirrors or glass onto a diffuse or
  // glossy surface, L S+ D): possible when some light reaches a surface with
  // a delta lobe directly and some surface has a non-delta lobe to receive.
  // Glossy surfaces, however smooth, count as non-specular.
  bool caustic_paths = false;
  std::string caustics_reason;  // why caustic paths are possible or not
  // Participating media: how many distinct ones shapes bound or the camera
  // sits in, and what kinds.
  int media = 0, heterogeneous_media = 0, chromatic_media = 0;
  bool camera_in_medium = false;
  // Paths must track media and step through null (index-matched) surfaces;
  // where neither occurs the walk takes no medium branch at all.
  bool medium_walk = false;
  // Shapes, or the camera, moving over the shutter interval: camera rays
  // then draw a time, and only integrators that follow it may render the
  // scene.
  int moving_shapes = 0, moving_lights = 0;
  bool moving_camera = false;
  bool motion = false;
  // Spectral transport: whether paths carry wavelengths, and why (what the
  // scene holds, or a render setting that decided it); the materials, by
  // plugin name, that cannot be rendered spectrally yet.
  bool spectral = false;
  std::string spectral_reason;
  std::vector<std::string> rgb_only_materials;
  // How a point to be lit chooses its light: through the light tree where
  // the tree holds two emitters or more (only then does the choice depend
  // on the point), by power otherwise; and why.
  bool light_tree = false;
  std::string light_selection_reason;
};

// A colour the scene file gave as a spectrum, for the analysis to weigh.
struct GivenSpectrum {
  SourceLocation where;
  std::string owner;      // the element it was given to: bsdf, emitter, medium, ...
  std::string parameter;  // its name there
  std::shared_ptr<const SampledSpectrum> spectrum;
};

// A spectrum renders spectrally when it lies this far (lift_misfit) from
// the smooth spectrum of its colour.
inline constexpr double kSpectrumMisfitThreshold = 0.05;

// Looks at the scene's materials, lights and camera; whether a light
// reaches a delta surface is decided by shadow rays from 256 points spread
// over each such surface to every light, and by 256 rays from each light. Spectral transport is chosen for
// a dispersive dielectric, a conductor whose eta and k are given as
// spectra, or an emission or reflectance spectrum RGB would misrepresent
// (among `spectra`); not where media or null boundaries would then refuse to
// render.
SceneFeatures analyze_scene(const Scene& scene, bool textures, const std::vector<GivenSpectrum>& spectra = {});

// Spectral or RGB transport as a render setting (or the scene file, `why`)
// decides, in place of the analysis's choice.
void force_spectral(SceneFeatures& f, bool spectral, const std::string& why = "forced by the render settings");

// The light tree or the choice by power, as a render setting decides, in
// place of the analysis's choice.
void force_light_tree(SceneFeatures& f, bool tree, const std::string& why = "forced by the render settings");
// A few lines for `caustica info`.
std::string describe(const SceneFeatures& features);
// Its line on the transport mode, and whether a render's log should print
// it (spectral transport, or RGB where something called for spectral).
std::string describe_transport(const SceneFeatures& features);
bool transport_worth_telling(const SceneFeatures& features);

}  // namespace caustica
