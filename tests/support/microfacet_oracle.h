#pragma once

// The microfacet model written out independently of core/bsdf, in double:
// Smith's Lambda in closed form and the directional albedo of a rough
// mirror or rough dielectric interface by quadrature over microfacet
// normals. Tests compare the BSDFs' sampling and evaluation against it.

#include "core/math/vec.h"

namespace caustica::test {

struct MicrofacetModel {
  bool ggx = true;  // else Beckmann
  double alpha_u = 0.1, alpha_v = 0.1;
};

// Smith's Lambda for direction w (w.z != 0). With tan theta = t and the
// roughness projected on w's azimuth, alpha^2 = (x^2 au^2 + y^2 av^2) /
// (x^2 + y^2): GGX (-1 + sqrt(1 + alpha^2 t^2)) / 2; Beckmann with
// a = 1 / (alpha t), (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)).
double smith_lambda(const MicrofacetModel& model, Vec3 w);

// Unpolarised Fresnel reflectance of a smooth interface at cosine c of the
// angle of incidence, eta the index across over the index on the incident
// side; 1 past the critical angle.
double fresnel_reflectance(double c, double eta);

// The interface below the surface a ray from wo meets.
struct Interface {
  bool dielectric = false;  // else a perfect mirror (Fresnel 1)
  // Index across the interface over the index on wo's side.
  double eta = 1.5;
};

// Reflected and refracted shares of the albedo. Importance transport adds
// them; radiance transport scales the refracted share by 1 / eta^2.
struct MicrofacetAlbedo {
  double reflected = 0, refracted = 0;
  double importance() const { return reflected + refracted; }
  double radiance(double eta) const { return reflected + refracted / (eta * eta); }
};

// The directional albedo from wo (wo.z > 0) under single scattering with
// height-correlated masking-shadowing: the integral over microfacet normals
// m of D(m) (wo.m) / wo.z times, for the reflected and the refracted
// direction wi, the Fresnel share times 1 / (1 + Lambda(wo) + Lambda(wi)).
// The midpoint rule on the slope distribution's inverse cumulative, `n` by
// 2n points.
MicrofacetAlbedo microfacet_albedo(const MicrofacetModel& model, const Interface& interface, Vec3 wo, int n);

}  // namespace caustica::test
