#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/film/film.h"
#include "core/geometry/ray.h"
#include "core/geometry/reference_point.h"
#include "core/math/color.h"
#include "core/registry/param_spec.h"
#include "core/registry/plugin.h"
#include "core/sampling/sampler.h"

namespace caustica {

class Medium;
class Properties;

// Importance arriving at a reference point from the camera, for connecting
// light paths to the lens.
struct WiSample {
  Vec3 wi;        // unit direction from the reference point to the lens
  Color We;       // importance carried along -wi
  float pdf = 0;  // solid angle density at the reference point
  Vec3 p_lens;
  Vec2 raster;  // where the connection lands on the film, in pixels
};

// The slab a camera sees: depths along `forward`, measured from `position`
// (render space), between near_clip and far_clip.
struct ClipPlanes {
  Vec3 position, forward;
  float near_clip = 0, far_clip = 0;
};

// A camera. Raster coordinates run over [0, width] x [0, height] in pixels,
// y downward; the importance We is normalised so that one sample per pixel
// of a light path splatted at its raster position estimates the pixel.
class Sensor : public Plugin {
 public:
  // The ray leaves at `time` (see Ray::time), from where the camera stands then.
  virtual Ray generate_ray(Vec2 raster, Vec2 u_lens, float time = 0) const = 0;
  // Whether generate_ray and sample_Wi use their lens sample; a pinhole
  // does not, and then none is drawn.
  virtual bool has_lens() const { return false; }
  // Whether every ray leaves along one direction (orthographic): then
  // pdf_We's density is per unit area of the film, pdf_dir being a delta.
  virtual bool delta_direction() const { return false; }
  // Importance emitted along `ray` (which starts on the lens, at ray.time)
  // and its raster position.
  virtual Color We(const Ray& ray, Vec2* raster) const = 0;
  virtual void pdf_We(const Ray& ray, float* pdf_pos, float* pdf_dir) const = 0;
  virtual std::optional<WiSample> sample_Wi(const ReferencePoint& ref, Vec2 u) const = 0;
  virtual ClipPlanes clip_planes() const = 0;
  // Whether the camera moves over the shutter (MovingSensor).
  virtual bool moves() const { return false; }

  const std::shared_ptr<Film>& film() const { return film_; }
  const std::shared_ptr<Sampler>& sampler() const { return sampler_; }
  // The medium the camera sits in (a nested <medium>), null for vacuum.
  const Medium* medium() const { return medium_.get(); }
  // The shutter interval, in the scene's time: moving shapes' and cameras' keys span it.
  double shutter_open() const { return shutter_open_; }
  double shutter_close() const { return shutter_close_; }

 protected:
  // Takes the nested film and sampler, or an hdrfilm and an independent
  // sampler with their default parameters.
  explicit Sensor(const Properties& props);

 private:
  std::shared_ptr<Film> film_;
  std::shared_ptr<Sampler> sampler_;
  std::shared_ptr<const Medium> medium_;
  double shutter_open_ = 0, shutter_close_ = 0;
};

// near_clip, far_clip, shutter_open and shutter_close, as every sensor
// declares them.
std::vector<ParamSpec> sensor_params();

}  // namespace caustica
