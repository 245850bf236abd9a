#include "core/sampling/piecewise_constant_2d.h"

#include <algorithm>
#include <cmath>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::vector<float> row_sums(std::span<const float> weights, int width, int height) {
  std::vector<float> sums(size_t(height), 0.0f);
  for (int y = 0; y < height; ++y) {
    double sum = 0;
    for (int x = 0; x < width; ++x) sum += weights[size_t(y) * width + x];
    sums[size_t(y)] = float(sum);
  }
  return sums;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

PiecewiseConstant2D::PiecewiseConstant2D(std::span<const float> weights, int width, int height)
    : width_(width), height_(height), rows_(row_sums(weights, width, height)) {
  columns_.resize(size_t(height));
  for (int y = 0; y < height; ++y)
    if (rows_.pmf(y) > 0) columns_[size_t(y)].emplace(weights.subspan(size_t(y) * width, size_t(width)));
}

Vec2 PiecewiseConstant2D::sample(Vec2 u, float* pdf) const {
  float row_pmf = 0, u_row = 0, column_pmf = 0, u_column = 0;
  const int y = rows_.sample(u.x, &row_pmf, &u_row);
  const int x = columns_[size_t(y)]->sample(u.y, &column_pmf, &u_column);
  *pdf = row_pmf * column_pmf * float(width_) * float(height_);
  // Kept inside the cell (a sum rounding up would cross into the next).
  const float cx = std::min(float(x) + u_column, std::nextafter(float(x + 1), 0.0f));
  const float cy = std::min(float(y) + u_row, std::nextafter(float(y + 1), 0.0f));
  return {cx / float(width_), cy / float(height_)};
}

float PiecewiseConstant2D::pdf(Vec2 p) const {
  const int x = std::clamp(int(p.x * float(width_)), 0, width_ - 1);
  const int y = std::clamp(int(p.y * float(height_)), 0, height_ - 1);
  if (!columns_[size_t(y)]) return 0;
  return rows_.pmf(y) * columns_[size_t(y)]->pmf(x) * float(width_) * float(height_);
}

}  // namespace caustica
