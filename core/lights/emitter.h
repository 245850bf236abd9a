#pragma once

#include <memory>
#include <optional>
#include <stdexcept>

#include "core/color/spectrum_to_rgb.h"
#include "core/geometry/bounds.h"
#include "core/geometry/interaction.h"
#include "core/geometry/reference_point.h"
#include "core/lights/light_bounds.h"
#include "core/math/color.h"
#include "core/math/sampled_spectrum.h"
#include "core/registry/plugin.h"
#include "core/spectral/wavelengths.h"

namespace caustica {

class Medium;
class Shape;

// An emitter's light given as a spectrum, with the colour RGB transport
// takes for it.
class MeasuredEmission {
 public:
  explicit MeasuredEmission(std::shared_ptr<const SampledSpectrum> spectrum)
      : spectrum_(std::move(spectrum)), rgb_(spectrum_to_rgb(*spectrum_)) {
    channel_ = rgb_.g >= rgb_.r && rgb_.g >= rgb_.b ? 1 : (rgb_.r >= rgb_.b ? 0 : 2);
  }
  // The spectrum times the number that makes its colour `rgb` (read off
  // the colour's largest channel).
  Color at(Color rgb, const Wavelengths& w) const {
    const float scale = rgb_[channel_] > 0 ? rgb[channel_] / rgb_[channel_] : 0;
    return spectrum_at(*spectrum_, w) * scale;
  }

 private:
  std::shared_ptr<const SampledSpectrum> spectrum_;
  Color rgb_;
  int channel_ = 1;
};

// Incident light sampled toward a reference point.
struct LiSample {
  Vec3 wi;        // unit direction from the reference point to the light
  Color Li;       // radiance arriving along -wi (intensity / d^2 for point lights)
  float pdf = 0;  // solid angle density, or the discrete probability for delta lights
  bool is_delta = false;
  Vec3 p, p_error, n;  // the light's point; n zero for point lights and the environment
  bool is_infinite = false;
};

// An emitted ray, for tracing light from the emitters.
struct LeSample {
  Ray ray;
  Vec3 n;  // surface normal at the origin, zero if none
  Color Le;
  float pdf_pos = 0;  // area density (or 1 for a delta position)
  float pdf_dir = 0;  // solid angle density of the direction
  Vec2 uv;            // surface parameters at the origin, for a textured emitter
};

class Emitter : public Plugin {
 public:
  // Called once the scene's extent is known (the environment needs it).
  virtual void prepare(const Bounds3&) {}
  // Only area emitters can be nested in a shape; the others refuse.
  virtual void attach_shape(const Shape*) {
    throw std::invalid_argument("only an area emitter can be nested in a shape");
  }
  virtual bool is_area() const { return false; }

  virtual std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2 u) const = 0;
  // The density sample_Li would have had for the direction wi reaching
  // `on_light` (unused by the environment).
  virtual float pdf_Li(const ReferencePoint& ref, Vec3 wi, const SurfaceInteraction& on_light) const = 0;
  // Radiance leaving a point of the emitter's surface in direction w.
  virtual Color L(const SurfaceInteraction&, Vec3) const { return {}; }
  // Radiance of an infinite emitter arriving along -d at `time` (see
  // Ray::time).
  virtual Color Le_infinite(Vec3, float) const { return {}; }

  // An emitted ray; a moving light emits from where it is at `time` (see
  // Ray::time), and the caller gives the ray that time.
  virtual std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2 u_dir, float time = 0) const = 0;
  virtual void pdf_Le(const Ray& ray, Vec3 n, float* pdf_pos, float* pdf_dir) const = 0;
  virtual Color power() const = 0;
  // Where the emitter is and which way it shines, for the light tree;
  // none for lights that are everywhere (the environment, directional
  // lights) or that move, which the tree leaves to the power-based choice.
  virtual std::optional<LightBounds> light_bounds() const { return std::nullopt; }

  virtual bool is_delta() const { return false; }
  virtual bool is_infinite() const { return false; }
  // Whether only paths traced from the lights can carry its light (it emits
  // from each point in one direction, which nothing else finds).
  virtual bool seen_by_light_paths_only() const { return false; }
  // Whether the light moves over the shutter (MovingEmitter).
  virtual bool moves() const { return false; }
  // An environment a ray leaving the scene can meet: infinitely far and
  // not a delta in direction (a directional light is met by no ray).
  bool is_environment() const { return is_infinite() && !is_delta(); }

  // The medium light paths start in (null: vacuum): a nested <medium>, or
  // for an area emitter on a shape that bounds media the shape's exterior.
  const Medium* medium() const { return medium_.get(); }
  void set_medium(std::shared_ptr<const Medium> medium) { medium_ = std::move(medium); }

  // Where the scene gave the emitter's light as a spectrum: its radiance
  // (intensity, irradiance) is then that spectrum times a number, and the
  // colours the emitter returns are the spectrum's colour times it.
  const MeasuredEmission* measured_emission() const { return measured_ ? &*measured_ : nullptr; }

 protected:
  // Called by an emitter's constructor with the spectrum its emission
  // parameter was given as (null: an RGB colour).
  void set_measured_emission(std::shared_ptr<const SampledSpectrum> spectrum) {
    if (spectrum) measured_ = MeasuredEmission(std::move(spectrum));
  }

 private:
  std::shared_ptr<const Medium> medium_;
  std::optional<MeasuredEmission> measured_;
};

}  // namespace caustica
