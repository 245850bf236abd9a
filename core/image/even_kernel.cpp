#include "core/image/even_kernel.h"

namespace caustica {

double EvenKernel::total() const {
  double sum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) sum += (x == 0 ? 1 : 2) * (y == 0 ? 1 : 2) * quadrant[size_t(y) * width + x];
  return sum;
}

}  // namespace caustica
