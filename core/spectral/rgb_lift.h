#pragma once

#include "core/math/color.h"
#include "core/math/sampled_spectrum.h"
#include "core/spectral/wavelengths.h"

namespace caustica {

// RGB values of a scene, lifted to the spectra a spectral path reads at its
// wavelengths (each returned channel i holds the value at w.nm[i]). All go
// through the build's RGB-to-spectrum table (core/color/rgb_spectrum_table.h).

// A reflectance (or transmittance), clamped to [0, 1]: its smooth spectrum
// within [0, 1], whose colour lit by D65 is rgb.
Color lift_reflectance(Color rgb, const Wavelengths& w);

// A value that may exceed 1 (at least 0): the spectrum of rgb / (2 m)
// scaled by 2 m, m its largest channel, so that the fitted part stays
// inside the table's cube away from its saturated faces.
Color lift_unbounded(Color rgb, const Wavelengths& w);

// Emitted radiance: the unbounded spectrum of rgb times D65, normalised so
// that RGB white emits D65 with luminance 1 and every colour converts back
// (spectral_to_rgb) to itself.
Color lift_illuminant(Color rgb, const Wavelengths& w);

// How far a spectrum given in a scene lies from the smooth spectra RGB
// transport stands for: from the illuminant lifted from its colour, or the
// reflectance lifted from its colour under D65. The integral of their
// difference's magnitude over that of the spectrum, 400 to 700 nm at 1 nm.
double lift_misfit(const SampledSpectrum& s, bool illuminant);

}  // namespace caustica
