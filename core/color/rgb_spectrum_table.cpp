#include "core/color/rgb_spectrum_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/color/rgb_spectrum_fit.h"
#include "core/install/data_files.h"

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

constexpr char kMagic[8] = {'C', 'R', 'G', 'B', 'S', 'P', 'E', 'C'};

double smoothstep(double t) { return t * t * (3 - 2 * t); }

// The flat spectrum of value v: S(t) = v.
double inverse_sigmoid(double v) {
  if (v <= 0) return -INFINITY;
  if (v >= 1) return INFINITY;
  return (v - 0.5) / std::sqrt(v * (1 - v));
}

std::array<double, 3> entry_colour(int largest, double z, double x, double y) {
  std::array<double, 3> rgb;
  rgb[size_t(largest)] = z;
  rgb[size_t((largest + 1) % 3)] = x * z;
  rgb[size_t((largest + 2) % 3)] = y * z;
  return rgb;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

RgbSpectrumTable RgbSpectrumTable::compute(int resolution) {
  RgbSpectrumTable table;
  const int n = resolution;
  table.resolution_ = n;
  table.z_.resize(size_t(n));
  for (int k = 0; k < n; ++k) table.z_[size_t(k)] = float(smoothstep(smoothstep(double(k) / (n - 1))));
  table.coefficients_.assign(size_t(3) * size_t(n) * n * n * 3, 0.0f);
  std::vector<float> errors(size_t(3) * n * n * n, 0.0f);
  const auto axis = [n](int i) { return double(i) / (n - 1); };

  const auto fit_entry = [&](int largest, int zi, int yi, int xi, const std::array<double, 3>& start) {
    const SigmoidFit fit =
        fit_sigmoid_reflectance(entry_colour(largest, table.z_[size_t(zi)], axis(xi), axis(yi)), start);
    const size_t at = table.index(largest, zi, yi, xi);
    for (int m = 0; m < 3; ++m) table.coefficients_[at + size_t(m)] = float(fit.c[size_t(m)]);
    errors[at / 3] = float(fit.error);
    return fit.c;
  };
  const auto stored = [&](int largest, int zi, int yi, int xi) {
    const size_t at = table.index(largest, zi, yi, xi);
    return std::array<double, 3>{table.coefficients_[at], table.coefficients_[at + 1], table.coefficients_[at + 2]};
  };

  // Fitting starts on a plane of middling brightness, from its grey corner
  // (x = y = 1) outward, each entry from its neighbour's solution; then
  // each line of constant x and y runs up and down from that plane.
  const int start_plane = n / 5;
  for (int largest = 0; largest < 3; ++largest) {
    for (int yi = n - 1; yi >= 0; --yi)
      for (int xi = n - 1; xi >= 0; --xi) {
        std::array<double, 3> start{0, 0, inverse_sigmoid(table.z_[size_t(start_plane)])};
        if (xi < n - 1)
          start = stored(largest, start_plane, yi, xi + 1);
        else if (yi < n - 1)
          start = stored(largest, start_plane, yi + 1, xi);
        fit_entry(largest, start_plane, yi, xi, start);
      }
    tbb::parallel_for(0, n * n, [&](int line) {
      const int yi = line / n, xi = line % n;
      std::array<double, 3> c = stored(largest, start_plane, yi, xi);
      for (int zi = start_plane + 1; zi < n; ++zi) c = fit_entry(largest, zi, yi, xi, c);
      c = stored(largest, start_plane, yi, xi);
      for (int zi = start_plane - 1; zi >= 0; --zi) c = fit_entry(largest, zi, yi, xi, c);
    });
  }
  table.worst_error_ = *std::max_element(errors.begin(), errors.end());
  return table;
}

void RgbSpectrumTable::write(const std::filesystem::path& file) const {
  // Written beside the target and renamed over it, so that a reader never
  // sees half a table.
  const std::filesystem::path partial = file.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    const int32_t n = resolution_;
    out.write(kMagic, sizeof kMagic);
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(&worst_error_), sizeof worst_error_);
    out.write(reinterpret_cast<const char*>(z_.data()), std::streamsize(z_.size() * sizeof(float)));
    out.write(reinterpret_cast<const char*>(coefficients_.data()),
              std::streamsize(coefficients_.size() * sizeof(float)));
    if (!out) throw std::runtime_error(partial.string() + ": could not be written");
  }
  std::filesystem::rename(partial, file);
}

RgbSpectrumTable RgbSpectrumTable::read(const std::filesystem::path& file) {
  const auto fail = [&](const std::string& problem) { return std::runtime_error(file.string() + ": " + problem); };
  std::ifstream in(file, std::ios::binary);
  if (!in) throw fail("cannot be opened (the build makes it with make_rgb_spectrum_table)");
  in.seekg(0, std::ios::end);
  const uint64_t length = uint64_t(in.tellg());
  in.seekg(0);
  char magic[sizeof kMagic];
  int32_t n = 0;
  RgbSpectrumTable table;
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    throw fail("is not an RGB-to-spectrum table (it does not start with CRGBSPEC)");
  if (!in.read(reinterpret_cast<char*>(&n), sizeof n) || n < 2 || n > 256)
    throw fail("declares a resolution of " + std::to_string(n) + "; it must be from 2 to 256");
  table.resolution_ = n;
  table.z_.resize(size_t(n));
  table.coefficients_.resize(size_t(3) * size_t(n) * n * n * 3);
  const uint64_t expected = sizeof kMagic + 8 + 4 * (table.z_.size() + table.coefficients_.size());
  if (length != expected)
    throw fail("holds " + std::to_string(length) + " bytes; resolution " + std::to_string(n) + " needs " +
               std::to_string(expected));
  in.read(reinterpret_cast<char*>(&table.worst_error_), sizeof table.worst_error_);
  in.read(reinterpret_cast<char*>(table.z_.data()), std::streamsize(table.z_.size() * sizeof(float)));
  in.read(reinterpret_cast<char*>(table.coefficients_.data()),
          std::streamsize(table.coefficients_.size() * sizeof(float)));
  if (!in) throw fail("could not be read to its end");
  for (size_t k = 0; k < table.z_.size(); ++k)
    if (!(table.z_[k] >= (k == 0 ? 0.0f : table.z_[k - 1])) || !(table.z_[k] <= 1))
      throw fail("its brightness samples do not increase from 0 to 1");
  for (float c : table.coefficients_)
    if (!std::isfinite(c)) throw fail("holds a coefficient that is not finite");
  return table;
}

std::filesystem::path RgbSpectrumTable::built_path() {
  return data_file("rgb_spectrum_table.bin", CAUSTICA_RGB_SPECTRUM_TABLE);
}

const RgbSpectrumTable& RgbSpectrumTable::built() {
  static const RgbSpectrumTable table = read(built_path());
  return table;
}

SigmoidSpectrum RgbSpectrumTable::lookup(std::array<float, 3> rgb) const {
  for (float& v : rgb) v = std::clamp(std::isnan(v) ? 0.0f : v, 0.0f, 1.0f);
  SigmoidSpectrum s;
  if (rgb[0] == rgb[1] && rgb[1] == rgb[2]) {
    s.c = {0, 0, float(inverse_sigmoid(rgb[0]))};
    return s;
  }
  const int largest = rgb[0] >= rgb[1] ? (rgb[0] >= rgb[2] ? 0 : 2) : (rgb[1] >= rgb[2] ? 1 : 2);
  const float z = rgb[size_t(largest)];
  const float x = rgb[size_t((largest + 1) % 3)] / z, y = rgb[size_t((largest + 2) % 3)] / z;
  const int n = resolution_;
  const int zi = int(std::clamp<std::ptrdiff_t>(std::upper_bound(z_.begin(), z_.end(), z) - z_.begin() - 1, 0, n - 2));
  const float tz = (z - z_[size_t(zi)]) / (z_[size_t(zi) + 1] - z_[size_t(zi)]);
  const float fx = x * float(n - 1), fy = y * float(n - 1);
  const int xi = std::min(int(fx), n - 2), yi = std::min(int(fy), n - 2);
  const float tx = fx - float(xi), ty = fy - float(yi);
  for (int m = 0; m < 3; ++m) {
    float sum = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
      const float w = (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty) * (dz ? tz : 1 - tz);
      sum += w * coefficients_[index(largest, zi + dz, yi + dy, xi + dx) + size_t(m)];
    }
    s.c[size_t(m)] = sum;
  }
  return s;
}

}  // namespace caustica
