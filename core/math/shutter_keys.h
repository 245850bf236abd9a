#pragma once

#include <string>
#include <vector>

namespace caustica {

// Why keys at `times` cannot carry something over the shutter [open,
// close]: fewer than two, not increasing, a shutter that never opens, keys
// that do not run from its opening to its closing, or keys not evenly
// spaced (Embree's time steps are). Empty when they can.
std::string shutter_keys_problem(const std::vector<double>& times, double open, double close);

}  // namespace caustica
