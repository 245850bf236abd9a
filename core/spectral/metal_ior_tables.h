#pragma once

#include <span>
#include <string_view>
#include <vector>

namespace caustica {

// One measured sample of a metal's complex index of refraction.
struct MetalIorSample {
  float nm, eta, k;
};

// Measured optical constants by the names Mitsuba 3 gives them (chemical symbols, "_palik" for Palik's handbook's
// values where Mitsuba has both), wavelengths increasing; empty span for an unknown name. Ag, Al, Au and Cu cover
// 360-830 nm at the spacing of their publications (metal_ior_tables.cpp names them); the others are Mitsuba's
// tables (metal_ior_data.inc), some of which stop short of 830 nm. Between samples, interpolate.
std::span<const MetalIorSample> metal_ior_table(std::string_view symbol);

// Every name metal_ior_table knows, Ag, Al, Au and Cu first.
std::vector<std::string_view> metal_ior_names();

// Whether Mitsuba 3 accepts the name although caustica has no table for it.
bool metal_ior_unavailable(std::string_view symbol);

}  // namespace caustica
