// make_rgb_spectrum_table OUT [RESOLUTION]: computes the RGB-to-spectrum
// table (core/color/rgb_spectrum_table.h) at build time and writes it to
// OUT; prints how long it took and its largest fit error.

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include "core/color/rgb_spectrum_table.h"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: %s OUT [RESOLUTION]\n", argv[0]);
    return 2;
  }
  try {
    const int resolution = argc == 3 ? std::stoi(argv[2]) : 64;
    const auto start = std::chrono::steady_clock::now();
    const auto table = caustica::RgbSpectrumTable::compute(resolution);
    table.write(argv[1]);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("RGB-to-spectrum table %d^3 x 3 in %.1f s, largest fit error %.3g -> %s\n", resolution, seconds,
                double(table.worst_fit_error()), argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_rgb_spectrum_table: %s\n", e.what());
    return 1;
  }
  return 0;
}
