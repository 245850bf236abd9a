#include "core/image/image_metrics.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

std::array<int, 3> channel_indices(const Image& image, const char* prefix, const char* what) {
  std::array<int, 3> out;
  const char* names[] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    out[c] = image.channel_index(std::string(prefix) + names[c]);
    if (out[c] < 0) throw std::invalid_argument(std::string(what) + " has no " + prefix + names[c] + " channel");
  }
  return out;
}

std::string size_text(const Image& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

// A non-finite value would make every metric non-finite: refused, naming
// the first pixel that holds one and how many there are.
void require_finite(const Image& image, const std::array<int, 3>& index, const char* what) {
  const char* names[] = {"R", "G", "B"};
  const size_t pixels = size_t(image.width) * image.height, nc = image.channels.size();
  size_t count = 0, first = 0;
  int first_channel = 0;
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(image.pixels[p * nc + index[c]]) && count++ == 0) {
        first = p;
        first_channel = c;
      }
  if (count == 0) return;
  char text[200];
  std::snprintf(text, sizeof text, "%s has %zu non-finite value%s, the first at pixel (%zu, %zu) in %s (%g)", what,
                count, count == 1 ? "" : "s", first % size_t(image.width), first / size_t(image.width),
                names[first_channel], double(image.pixels[first * nc + index[first_channel]]));
  throw std::invalid_argument(text);
}

bool has_variance(const Image& image) {
  return image.channel_index("variance.R") >= 0 && image.channel_index("variance.G") >= 0 &&
         image.channel_index("variance.B") >= 0;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

EstimatedError estimated_error(const Image& image, double rel_epsilon) {
  if (!has_variance(image)) return {};
  const auto beauty = channel_indices(image, "", "the image");
  const auto variance = channel_indices(image, "variance.", "the image");
  const size_t pixels = size_t(image.width) * image.height, nc = image.channels.size();
  double sum = 0, rel_sum = 0;
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c) {
      const double x = image.pixels[p * nc + beauty[c]], v = image.pixels[p * nc + variance[c]];
      sum += v;
      rel_sum += v / (x * x + rel_epsilon);
    }
  const double n = 3.0 * double(pixels);
  return {pixels ? sum / n : 0, pixels ? rel_sum / n : 0, true};
}

ErrorMetrics compare_images(const Image& image, const Image& reference, double rel_epsilon) {
  if (image.width != reference.width || image.height != reference.height)
    throw std::invalid_argument(std::string("the image is ") + size_text(image) + " but the reference is " +
                                size_text(reference));
  const auto x_index = channel_indices(image, "", "the image");
  const auto r_index = channel_indices(reference, "", "the reference");
  require_finite(image, x_index, "the image");
  require_finite(reference, r_index, "the reference");
  const size_t pixels = size_t(image.width) * image.height;
  const size_t nx = image.channels.size(), nr = reference.channels.size();
  double squared = 0, rel_squared = 0, absolute = 0;
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c) {
      const double x = image.pixels[p * nx + x_index[c]], r = reference.pixels[p * nr + r_index[c]];
      const double d = x - r;
      squared += d * d;
      rel_squared += d * d / (r * r + rel_epsilon);
      absolute += std::abs(d);
    }
  const double n = pixels ? 3.0 * double(pixels) : 1.0;
  ErrorMetrics m;
  m.mse = squared / n;
  m.rel_mse = rel_squared / n;
  m.mae = absolute / n;
  m.reference = estimated_error(reference, rel_epsilon);
  m.image = estimated_error(image, rel_epsilon);
  m.mse_corrected = m.mse - m.reference.mse;
  m.rel_mse_corrected = m.rel_mse - m.reference.rel_mse;
  return m;
}

}  // namespace caustica
