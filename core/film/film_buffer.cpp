#include "core/film/film_buffer.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace caustica {

FilmBuffer::FilmBuffer(int width, int height, std::vector<std::string> channels)
    : width_(width), height_(height), channels_(std::move(channels)) {
  const size_t pixels = size_t(width) * height;
  weighted_sum_.assign(pixels * channels_.size(), 0);
  weight_sum_.assign(pixels, 0);
  weight2_sum_.assign(pixels, 0);
  w2x_.assign(pixels * 3, 0);
  w2x2_.assign(pixels * 3, 0);
  count_.assign(pixels, 0);
}

void FilmBuffer::add_sample(SampleId id, std::span<const float> values, float weight) {
  bool finite = std::isfinite(weight);
  for (float v : values) finite = finite && std::isfinite(v);
  if (!finite) {
    dropped_->count.fetch_add(1);
    std::lock_guard lock(dropped_->mutex);
    const auto key = [](SampleId s) { return std::tuple(s.pixel.y, s.pixel.x, s.index); };
    if (dropped_->first.pixel.x < 0 || key(id) < key(dropped_->first)) dropped_->first = id;
    return;
  }
  const size_t p = index(id.pixel);
  double* sum = &weighted_sum_[p * channels_.size()];
  for (size_t c = 0; c < channels_.size(); ++c) sum[c] += double(weight) * values[c];
  weight_sum_[p] += weight;
  const double w2 = double(weight) * weight;
  weight2_sum_[p] += w2;
  ++count_[p];
  for (size_t c = 0; c < std::min<size_t>(3, values.size()); ++c) {
    w2x_[p * 3 + c] += w2 * values[c];
    w2x2_[p * 3 + c] += w2 * values[c] * values[c];
  }
}

std::vector<float> FilmBuffer::resolve() const {
  std::vector<float> out(weighted_sum_.size(), 0);
  const size_t nc = channels_.size();
  for (size_t p = 0; p < weight_sum_.size(); ++p)
    if (weight_sum_[p] != 0)
      for (size_t c = 0; c < nc; ++c) out[p * nc + c] = float(weighted_sum_[p * nc + c] / weight_sum_[p]);
  return out;
}

std::vector<float> FilmBuffer::variance() const {
  std::vector<float> out(w2x_.size(), 0);
  const size_t nc = channels_.size();
  for (size_t p = 0; p < count_.size(); ++p) {
    const double n = count_[p], W = weight_sum_[p];
    if (n < 2 || W == 0) continue;
    for (size_t c = 0; c < std::min<size_t>(3, nc); ++c) {
      const double mean = weighted_sum_[p * nc + c] / W;
      const double spread = w2x2_[p * 3 + c] - 2 * mean * w2x_[p * 3 + c] + mean * mean * weight2_sum_[p];
      out[p * 3 + c] = float(std::max(0.0, spread) / (W * W) * n / (n - 1));
    }
  }
  return out;
}

SampleId FilmBuffer::first_dropped() const {
  std::lock_guard lock(dropped_->mutex);
  return dropped_->first;
}

}  // namespace caustica
