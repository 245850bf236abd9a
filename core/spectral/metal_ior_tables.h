#pragma once

#include <span>
#include <string_view>

namespace caustica {

// One measured sample of a metal's complex index of refraction.
struct MetalIorSample {
  float nm, eta, k;
};

// Measured optical constants by chemical symbol (Ag, Al, Au, Cu), wavelengths increasing; empty span for an unknown
// name. Each table covers at least 360-830 nm at the spacing of its publication (see metal_ior_tables.cpp for the
// sources); between samples, interpolate.
std::span<const MetalIorSample> metal_ior_table(std::string_view symbol);

}  // namespace caustica
