#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/math/color.h"
#include "core/math/sampled_spectrum.h"

namespace caustica {

// Parses "nm:value, nm:value, ..."; throws std::invalid_argument saying
// what is wrong (a malformed pair, wavelengths not increasing, a value that
// is not finite).
SampledSpectrum parse_spectrum_pairs(const std::string& text);
// Reads a .spd file: one "nm value" pair per line, '#' starting comments.
// Throws std::invalid_argument naming the line.
SampledSpectrum read_spd_file(const std::filesystem::path& file);

// Planck's law: the spectral radiance of a black body at `kelvin`, in
// W / (m^2 sr nm), at 5 nm steps over the CIE range.
SampledSpectrum blackbody(double kelvin);

// The spectrum integrated against the CIE 1931 colour matching functions
// (at 1 nm steps, tables interpolated linearly) over the integral of y, and
// taken from XYZ to linear Rec.709 (sRGB primaries, D65 white), as
// Mitsuba's RGB variants convert reflectance and emission spectra alike: a
// flat spectrum of value v has X = Y = Z = v (equal-energy white, a little
// pink in Rec.709), and D65's shape is an RGB grey.
Color spectrum_to_rgb(const SampledSpectrum& spectrum);

}  // namespace caustica
