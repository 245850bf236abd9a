#include "core/math/shutter_keys.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::string text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::string key_times_problem(const std::vector<double>& times) {
  if (times.size() < 2) return "an animation needs at least two <transform time=...> keys";
  for (size_t k = 1; k < times.size(); ++k)
    if (!(times[k] > times[k - 1]))
      return "the animation's key times must increase (key " + std::to_string(k + 1) + " at " +
             std::to_string(times[k]) + " follows one at " + std::to_string(times[k - 1]) + ")";
  return "";
}

std::string shutter_keys_problem(const std::vector<double>& times, double open, double close) {
  if (std::string problem = key_times_problem(times); !problem.empty()) return problem;
  if (!(close > open))
    return "the sensor's shutter is closed (shutter_open " + text(open) + ", shutter_close " + text(close) +
           "), so nothing can move during it: give it an interval";
  const double first = times.front(), last = times.back();
  const double tolerance = 1e-6 * std::max(1.0, std::abs(open) + std::abs(close));
  if (std::abs(first - open) > tolerance || std::abs(last - close) > tolerance)
    return "the animation's keys run from " + text(first) + " to " + text(last) +
           ", and must span the sensor's shutter, from " + text(open) + " to " + text(close);
  const double step = (last - first) / double(times.size() - 1);
  for (size_t k = 0; k < times.size(); ++k)
    if (std::abs(times[k] - (first + step * double(k))) > tolerance)
      return "the animation's key times must be evenly spaced (key " + std::to_string(k + 1) + " is at " +
             text(times[k]) + ", not " + text(first + step * double(k)) + ")";
  return "";
}

}  // namespace caustica
