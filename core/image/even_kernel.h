#pragma once

#include <vector>

namespace caustica {

// A convolution kernel symmetric in x and in y, kept as its quadrant:
// weight(dx, dy) for |dx| < width and |dy| < height. Spanning twice the
// image less one pixel, it reaches every pixel from every other.
struct EvenKernel {
  int width = 0, height = 0;
  std::vector<double> quadrant;  // row-major, (0, 0) first

  double at(int dx, int dy) const {
    return quadrant[size_t(dy < 0 ? -dy : dy) * size_t(width) + size_t(dx < 0 ? -dx : dx)];
  }
  // The sum over every offset, each quadrant weight counted for its mirror images.
  double total() const;
};

}  // namespace caustica
