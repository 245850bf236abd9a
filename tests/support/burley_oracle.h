#pragma once

// Burley's principled model (the 2012 notes, SIGGRAPH course "Physically
// Based Shading at Disney", and 2015's extension), written apart from the
// plugins in the notes' own forms, in double precision: the oracle of the
// principled and principledthin tests.

namespace caustica::test::burley {

struct Dir {
  double x, y, z;
};
double dot3(Dir a, Dir b);
Dir unit(Dir a);

// (1 - cos)^5, cos clamped to [0, 1].
double schlick(double cos);
// Exact unpolarised Fresnel reflectance meeting a facet at cos_i from the
// side of index n1 into n2.
double fresnel(double cos_i, double n1, double n2);

struct Alphas {
  double x, y;
};
// GGX's (alpha_x, alpha_y) from roughness and anisotropic (the notes' aspect
// sqrt(1 - 0.9 anisotropic)), at least 0.001.
Alphas alphas(double roughness, double anisotropic);
// Anisotropic GGX by the half vector's angles.
double ggx_D(Dir h, Alphas a);
// Smith's masking in the notes' "visibility" form G1 / (2 |cos|), which
// carries the 1 / (4 cos_l cos_v) of the microfacet model in pairs.
double ggx_visibility(Dir v, Alphas a);
// The diffuse lobe of the 2012 notes, (1 + (F_D90 - 1) F_L)(1 + (F_D90 - 1) F_V)
// with F_D90 = 0.5 + 2 roughness cos_d^2, blended by flatness with the
// Hanrahan-Krueger-like lobe, over pi.
double diffuse(double cos_l, double cos_v, double cos_d, double roughness, double flatness);

}  // namespace caustica::test::burley
