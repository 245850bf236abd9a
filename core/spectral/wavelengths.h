#pragma once

#include <array>
#include <cstdint>

#include "core/math/color.h"
#include "core/math/sampled_spectrum.h"

namespace caustica {

// The wavelengths a path carries in spectral mode. There are three, so that
// a path's values at them ride in the Color every part of the transport
// already passes around: channel i holds the value at wavelength i.
// Wavelength 0 is the hero (the one whose index of refraction decides a
// dispersive bounce).
struct Wavelengths {
  std::array<float, 3> nm{};
  std::array<float, 3> pdf{};  // each one's density per nm
};

// Where the wavelengths' paths part (a dispersive refraction sends each its
// own way) only the hero's is followed: the others' densities become 0 and
// the hero's a third, so that the estimators below weigh its value three
// times and ignore the others', in every estimate the sample makes from
// then on. That stays unbiased: whether a path meets dispersion does not
// depend on the wavelengths, and the hero alone follows the visible density.
void terminate_secondaries(Wavelengths& w);
bool secondaries_terminated(const Wavelengths& w);
// A path's values with the secondaries' set to zero, which they count for
// once terminated (so that roulette does not keep a path alive for them).
inline Color hero_only(Color c) { return {c.r, 0, 0}; }

// The range spectral mode samples, that of the CIE tables.
inline constexpr float kMinWavelengthNm = 360, kMaxWavelengthNm = 830;

// Wavelengths are drawn from a density that follows the eye's sensitivity,
// p(l) proportional to 1 / cosh^2(0.0072 (l - 538 nm)) over the range
// (Radziszewski et al. 2009), whose integral is a tanh and inverts in closed
// form.
float visible_wavelength_pdf(float nm);
float sample_visible_wavelength(float u);

// Three wavelengths from one uniform number u: the hero at u, the others at
// u + 1/3 and u + 2/3 (modulo 1) through the same inversion, so that each
// follows the density above and the three spread over the spectrum.
Wavelengths sample_wavelengths(float u);

// The wavelengths every path of a photon pass shares (photons and the
// camera paths that gather them must be at the same wavelengths): u of
// pass k is a random offset from `seed` plus k times the golden ratio,
// modulo 1, so that each pass's u is uniform and the passes spread evenly.
Wavelengths pass_wavelengths(uint64_t pass, uint64_t seed);

// A spectrum's values at the wavelengths.
inline Color spectrum_at(const SampledSpectrum& s, const Wavelengths& w) {
  return {float(s.at(w.nm[0])), float(s.at(w.nm[1])), float(s.at(w.nm[2]))};
}

// The CIE XYZ a path's spectral radiance `values` (at w) estimates: the
// average over the wavelengths of value x (x, y, z)(l) / pdf(l), over the
// integral of y, so that a flat spectrum of 1 gives X = Y = Z = 1, as
// spectrum_to_rgb converts spectra in scene files.
std::array<double, 3> spectral_to_xyz(Color values, const Wavelengths& w);
// The same in linear Rec.709.
Color spectral_to_rgb(Color values, const Wavelengths& w);

}  // namespace caustica
