#pragma once

#include <cstdint>
#include <optional>

#include "core/math/color.h"
#include "core/math/frame.h"
#include "core/registry/plugin.h"
#include "core/spectral/wavelengths.h"

namespace caustica {

// Radiance flows from lights to the camera; importance from the camera to
// lights (light tracing, photons). Refraction and shading normals are not
// symmetric between the two.
enum class TransportMode { Radiance, Importance };

// Lobe flags, combined with |.
enum BsdfLobe : uint32_t {
  kDiffuseReflection = 1u << 0,
  kDiffuseTransmission = 1u << 1,
  kGlossyReflection = 1u << 2,
  kGlossyTransmission = 1u << 3,
  kDeltaReflection = 1u << 4,
  kDeltaTransmission = 1u << 5,

  kDiffuse = kDiffuseReflection | kDiffuseTransmission,
  kGlossy = kGlossyReflection | kGlossyTransmission,
  kDelta = kDeltaReflection | kDeltaTransmission,
  kReflection = kDiffuseReflection | kGlossyReflection | kDeltaReflection,
  kTransmission = kDiffuseTransmission | kGlossyTransmission | kDeltaTransmission,
  // No scattering at all: light passes on unchanged (the boundary of a
  // medium, index-matched). The walk steps through such surfaces.
  kNull = 1u << 6,
};

struct BsdfContext {
  TransportMode mode = TransportMode::Radiance;
  Vec2 uv;
  // Surface tangents along u and v in the local shading frame, not unit
  // length (their lengths scale texture derivatives); bump and normal maps
  // build their perturbed frames from them.
  Vec3 dpdu{1, 0, 0}, dpdv{0, 1, 0};
  // In spectral mode, the path's wavelengths: values are returned at them
  // (channel i at wavelength i) rather than in RGB. Null in RGB mode.
  const Wavelengths* wavelengths = nullptr;
};

// A sampled direction. For a delta lobe f and pdf are the discrete lobe's
// weight and probability (eval and pdf of that direction are zero).
struct BsdfSample {
  Vec3 wi;
  Color f;
  float pdf = 0;
  uint32_t lobe = 0;
  float eta = 1;  // relative IOR along wi for transmission, 1 otherwise

  bool is_delta() const { return (lobe & kDelta) != 0; }
  bool is_transmission() const { return (lobe & kTransmission) != 0; }
};

// A scattering function in its local shading frame (normal = +z). wo and wi
// both point away from the surface.
class Bsdf : public Plugin {
 public:
  virtual uint32_t lobes() const = 0;
  virtual Color eval(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const = 0;
  virtual float pdf(const BsdfContext& ctx, Vec3 wo, Vec3 wi) const = 0;
  // u_lobe chooses among lobes, u the direction within one.
  virtual std::optional<BsdfSample> sample(const BsdfContext& ctx, Vec3 wo, float u_lobe, Vec2 u) const = 0;
  // Directional-hemispherical reflectance seen from wo, as written to the albedo AOV.
  virtual Color albedo(const BsdfContext& ctx, Vec3 wo) const = 0;
  // Whether the BSDF reads the context's tangents (dpdu, dpdv). Only then
  // does a surface transform them into the shading frame for it; a
  // material says false once its values cannot depend on them.
  virtual bool reads_tangents() const { return true; }
  // Whether it returns values at the context's wavelengths in spectral
  // mode; a scene holding one that does not is not rendered spectrally.
  virtual bool renders_spectral() const { return false; }
  // Whether where it sends light depends on the wavelength (a dispersive
  // dielectric): a spectral path meeting it goes on at its hero wavelength
  // alone, and the scene is rendered spectrally.
  virtual bool disperses() const { return false; }
};

}  // namespace caustica
