#pragma once

#include <string>
#include <vector>

namespace caustica {

// Why keys at `times` describe no motion: fewer than two, or not
// increasing. Empty when they do.
std::string key_times_problem(const std::vector<double>& times);

// Why keys at `times` cannot carry something over the shutter [open,
// close]: key_times_problem's reasons, a shutter that never opens, keys
// that do not run from its opening to its closing, or keys not evenly
// spaced (Embree's time steps are). Empty when they can.
std::string shutter_keys_problem(const std::vector<double>& times, double open, double close);

}  // namespace caustica
