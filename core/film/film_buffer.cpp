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
  mean_.assign(pixels * 3, 0);
  m2_.assign(pixels * 3, 0);
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
  const uint32_t n = ++count_[p];
  for (size_t c = 0; c < std::min<size_t>(3, values.size()); ++c) {
    double& mean = mean_[p * 3 + c];
    const double delta = values[c] - mean;
    mean += delta / n;
    m2_[p * 3 + c] += delta * (values[c] - mean);
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
  std::vector<float> out(m2_.size(), 0);
  for (size_t p = 0; p < count_.size(); ++p)
    if (count_[p] > 1)
      for (int c = 0; c < 3; ++c) out[p * 3 + c] = float(m2_[p * 3 + c] / (count_[p] - 1) / count_[p]);
  return out;
}

SampleId FilmBuffer::first_dropped() const {
  std::lock_guard lock(dropped_->mutex);
  return dropped_->first;
}

}  // namespace caustica
