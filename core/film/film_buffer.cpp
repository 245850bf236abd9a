#include "core/film/film_buffer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "core/film/reconstruction_filter.h"
#include "core/film/splat_list.h"

namespace caustica {

FilmBuffer::FilmBuffer(int width, int height, std::vector<std::string> channels, Moments moments)
    : width_(width), height_(height), channels_(std::move(channels)) {
  const size_t pixels = size_t(width) * height;
  weighted_sum_.assign(pixels * channels_.size(), {});
  weight_sum_.assign(pixels, {});
  if (moments == Moments::Kept) moments_.assign(pixels, {});
  count_.assign(pixels, 0);
}

void FilmBuffer::add_sample(SampleId id, std::span<const float> values, float weight, uint32_t samples) {
  bool finite = std::isfinite(weight);
  for (float v : values) finite = finite && std::isfinite(v);
  if (!finite) {
    dropped_->record(id, 1);
    return;
  }
  const size_t p = index(id.pixel);
  ExactSum* sum = &weighted_sum_[p * channels_.size()];
  for (size_t c = 0; c < channels_.size(); ++c) sum[c].add(double(weight) * values[c]);
  weight_sum_[p].add(weight);
  count_[p] += samples;
  if (!keeps_moments()) return;
  const double w2 = double(weight) * weight;
  MomentSums& m = moments_[p];
  m.w2 += w2;
  for (size_t c = 0; c < std::min<size_t>(3, values.size()); ++c) {
    m.w2x[c] += w2 * values[c];
    m.w2x2[c] += w2 * values[c] * values[c];
  }
}

void FilmBuffer::DropLog::record(SampleId id, uint64_t n) {
  count.fetch_add(n);
  std::lock_guard lock(mutex);
  const auto key = [](SampleId s) { return std::tuple(s.pixel.y, s.pixel.x, s.index); };
  if (first.pixel.x < 0 || key(id) < key(first)) first = id;
}

void FilmBuffer::add_splats(const SplatList& list, const ReconstructionFilter& filter, int y_begin, int y_end) {
  const float r = filter.radius();
  const double norm = 1.0 / (double(filter.integral()) * filter.integral());
  const size_t nc = channels_.size();
  std::vector<float> fx;  // the filter across the footprint's columns, evaluated once per splat
  for (const Splat& s : list.splats()) {
    // Pixel centres sit at half-integers; these are the ones within r.
    const int y0 = std::max(y_begin, int(std::ceil(s.raster.y - 0.5f - r)));
    const int y1 = std::min(y_end - 1, int(std::floor(s.raster.y - 0.5f + r)));
    if (y0 > y1) continue;
    const int x0 = std::max(0, int(std::ceil(s.raster.x - 0.5f - r)));
    const int x1 = std::min(width_ - 1, int(std::floor(s.raster.x - 0.5f + r)));
    fx.clear();
    for (int x = x0; x <= x1; ++x) fx.push_back(filter.eval(s.raster.x - (x + 0.5f)));
    for (int y = y0; y <= y1; ++y) {
      const float fy = filter.eval(s.raster.y - (y + 0.5f));
      if (fy == 0) continue;
      for (int x = x0; x <= x1; ++x) {
        const double w = norm * fy * fx[size_t(x - x0)];
        if (w == 0) continue;
        ExactSum* sum = &splat_sum_[index({x, y}) * nc + s.channel];
        sum[0].add(w * s.value.r);
        sum[1].add(w * s.value.g);
        sum[2].add(w * s.value.b);
      }
    }
  }
}

void FilmBuffer::enable_splats() {
  if (splat_sum_.empty()) splat_sum_.assign(weighted_sum_.size(), {});
}

void FilmBuffer::record_dropped(const SplatList& list) {
  if (list.dropped() > 0) dropped_->record(list.first_dropped(), list.dropped());
}

std::vector<float> FilmBuffer::resolve() const {
  std::vector<float> out(weighted_sum_.size());
  for (size_t p = 0; p < weight_sum_.size(); ++p) resolve_pixel(p, &out[p * channels_.size()]);
  return out;
}

void FilmBuffer::resolve_pixel(size_t p, float* out) const {
  const size_t nc = channels_.size();
  for (size_t c = 0; c < nc; ++c)
    out[c] = weight_sum_[p].value() != 0 ? float(weighted_sum_[p * nc + c].value() / weight_sum_[p].value()) : 0.0f;
  if (!splat_sum_.empty() && splat_paths_per_pixel_ > 0)
    for (size_t c = 0; c < nc; ++c) out[c] += float(splat_sum_[p * nc + c].value() / double(splat_paths_per_pixel_));
}

std::vector<float> FilmBuffer::variance() const {
  if (!keeps_moments()) throw std::logic_error("variance() of a film that keeps no moments");
  std::vector<float> out(moments_.size() * 3);
  for (size_t p = 0; p < count_.size(); ++p) variance_pixel(p, &out[p * 3]);
  return out;
}

void FilmBuffer::variance_pixel(size_t p, float* out) const {
  const size_t nc = channels_.size();
  const double n = count_[p], W = weight_sum_[p].value();
  for (size_t c = 0; c < 3; ++c) {
    out[c] = 0;
    if (n < 2 || W == 0 || c >= nc) continue;
    const double mean = weighted_sum_[p * nc + c].value() / W;
    const MomentSums& m = moments_[p];
    const double spread = m.w2x2[c] - 2 * mean * m.w2x[c] + mean * mean * m.w2;
    // The sums have a double's range and cannot overflow; a float can, so the
    // variance of radiance beyond about 1e19 is clamped to the largest one.
    const double variance = std::max(0.0, spread) / (W * W) * n / (n - 1);
    out[c] = float(std::min(variance, double(std::numeric_limits<float>::max())));
  }
}

namespace {
namespace CAUSTICA_UNITY_ID {

// Three floats whose sum is d: each takes what the previous left over.
void split_double(double d, float* out) {
  out[0] = float(d);
  const double rest = d - double(out[0]);
  out[1] = float(rest);
  out[2] = float(rest - double(out[1]));
}

double join_floats(const float* in) { return double(in[0]) + double(in[1]) + double(in[2]); }

// The two kinds of sum a film holds, alike for exporting and adding.
double value_of(const ExactSum& s) { return s.value(); }
double value_of(double s) { return s; }
double rest_of(const ExactSum& s) { return s.rest(); }
double rest_of(double) { return 0; }
void add_parts(ExactSum& s, double value, double rest) { s.add(ExactSum::from_parts(value, rest)); }
// An exported moment's rest is 0; an older file's is below half an ulp of
// its value, so the value is the sum to a double's precision.
void add_parts(double& s, double value, double) { s += value; }

// The rest of a sum is below 2^-53 of its value: scaled up, it stays in the
// range of floats wherever the value does.
constexpr int kRestScale = 64;

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

template <class Self, class F>
void FilmBuffer::for_each_sum(Self& film, size_t p, F&& f) {
  const size_t nc = film.channels_.size();
  for (size_t c = 0; c < nc; ++c) f(film.weighted_sum_[p * nc + c]);
  f(film.weight_sum_[p]);
  if (film.keeps_moments()) {
    auto& m = film.moments_[p];
    f(m.w2);
    for (auto& sum : m.w2x) f(sum);
    for (auto& sum : m.w2x2) f(sum);
  }
  if (!film.splat_sum_.empty())
    for (size_t c = 0; c < nc; ++c) f(film.splat_sum_[p * nc + c]);
}

std::vector<std::string> FilmBuffer::raw_channels(const std::string& prefix) const {
  std::vector<std::string> sums;
  for (const std::string& c : channels_) sums.push_back("sum." + c);
  sums.push_back("weight");
  if (keeps_moments()) {
    sums.push_back("weight2");
    // The moments of the first three channels (the beauty), whatever their names.
    for (const char* moment : {"w2x.", "w2x2."})
      for (size_t c = 0; c < 3; ++c) sums.push_back(moment + (c < channels_.size() ? channels_[c] : std::to_string(c)));
  }
  if (!splat_sum_.empty())
    for (const std::string& c : channels_) sums.push_back("splat." + c);
  std::vector<std::string> names;
  for (const std::string& s : sums)
    for (const char* part : {".0", ".1", ".2", ".3", ".4", ".5"}) names.push_back(prefix + s + part);
  names.push_back(prefix + "count");
  return names;
}

std::vector<float> FilmBuffer::export_raw() const {
  const size_t per_pixel = raw_channels("").size();
  std::vector<float> out(count_.size() * per_pixel);
  for (size_t p = 0; p < count_.size(); ++p) export_raw_pixel(p, &out[p * per_pixel]);
  return out;
}

void FilmBuffer::export_raw_pixel(size_t p, float* out) const {
  for_each_sum(*this, p, [&](const auto& sum) {
    split_double(value_of(sum), out);
    split_double(std::ldexp(rest_of(sum), kRestScale), out + 3);
    out += 6;
  });
  *out = float(count_[p]);
}

void FilmBuffer::add_raw(std::span<const float> raw, uint64_t splat_paths) {
  if (splat_paths > 0) enable_splats();
  splat_paths_per_pixel_ += splat_paths;
  const size_t per_pixel = raw_channels("").size();
  for (size_t p = 0; p < count_.size(); ++p) {
    const float* in = &raw[p * per_pixel];
    for_each_sum(*this, p, [&](auto& sum) {
      add_parts(sum, join_floats(in), std::ldexp(join_floats(in + 3), -kRestScale));
      in += 6;
    });
    count_[p] += uint32_t(*in);
  }
}

namespace {
namespace CAUSTICA_UNITY_ID {

// pack()'s header: whether splats follow, the splat paths, the dropped
// samples and the first of them (integers below 2^53, exact as doubles).
constexpr size_t kPackHeader = 6;

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void FilmBuffer::add(const FilmBuffer& other) {
  if (other.count_.size() != count_.size() || other.channels_ != channels_ || other.keeps_moments() != keeps_moments())
    throw std::invalid_argument("adding a film of another size, channels or moments");
  const auto add_all = [](std::vector<ExactSum>& to, const std::vector<ExactSum>& from) {
    for (size_t i = 0; i < from.size(); ++i) to[i].add(from[i]);
  };
  add_all(weighted_sum_, other.weighted_sum_);
  add_all(weight_sum_, other.weight_sum_);
  for (size_t p = 0; p < moments_.size(); ++p) {
    MomentSums& m = moments_[p];
    const MomentSums& o = other.moments_[p];
    m.w2 += o.w2;
    for (size_t c = 0; c < 3; ++c) {
      m.w2x[c] += o.w2x[c];
      m.w2x2[c] += o.w2x2[c];
    }
  }
  if (other.has_splats()) enable_splats();
  add_all(splat_sum_, other.splat_sum_);
  splat_paths_per_pixel_ += other.splat_paths_per_pixel_;
  for (size_t p = 0; p < count_.size(); ++p) count_[p] += other.count_[p];
  if (other.dropped_samples() > 0) dropped_->record(other.first_dropped(), other.dropped_samples());
}

void FilmBuffer::clear() {
  for (std::vector<ExactSum>* sums : {&weighted_sum_, &weight_sum_, &splat_sum_})
    std::fill(sums->begin(), sums->end(), ExactSum{});
  std::fill(moments_.begin(), moments_.end(), MomentSums{});
  std::fill(count_.begin(), count_.end(), 0u);
  splat_paths_per_pixel_ = 0;
  dropped_ = std::make_unique<DropLog>();
}

std::vector<double> FilmBuffer::pack() const {
  const SampleId first = first_dropped();
  std::vector<double> out{double(has_splats()),  double(splat_paths_per_pixel_), double(dropped_samples()),
                          double(first.pixel.x), double(first.pixel.y),          double(first.index)};
  out.reserve(kPackHeader + count_.size() * ((raw_channels("").size() - 1) / 3 + 1));
  for (size_t p = 0; p < count_.size(); ++p) {
    for_each_sum(*this, p, [&](const auto& sum) { out.insert(out.end(), {value_of(sum), rest_of(sum)}); });
    out.push_back(count_[p]);
  }
  return out;
}

void FilmBuffer::add_packed(std::span<const double> packed) {
  if (packed.size() < kPackHeader) throw std::invalid_argument("a packed film without its header");
  const bool splats = packed[0] != 0;
  if (splats) enable_splats();
  // The splat sums come last: a packed film without them leaves this film's alone.
  const size_t sums = (raw_channels("").size() - 1) / 6 - (has_splats() && !splats ? channels_.size() : 0);
  const size_t per_pixel = 2 * sums + 1;
  if (packed.size() != kPackHeader + count_.size() * per_pixel)
    throw std::invalid_argument("a packed film of " + std::to_string(packed.size()) +
                                " values does not fit a film that takes " +
                                std::to_string(kPackHeader + count_.size() * per_pixel));
  splat_paths_per_pixel_ += uint64_t(packed[1]);
  if (packed[2] > 0) dropped_->record({{int(packed[3]), int(packed[4])}, uint64_t(packed[5])}, uint64_t(packed[2]));
  const double* in = packed.data() + kPackHeader;
  for (size_t p = 0; p < count_.size(); ++p) {
    size_t k = 0;
    for_each_sum(*this, p, [&](auto& sum) {
      if (k++ >= sums) return;
      add_parts(sum, in[0], in[1]);
      in += 2;
    });
    count_[p] += uint32_t(*in++);
  }
}

SampleId FilmBuffer::first_dropped() const {
  std::lock_guard lock(dropped_->mutex);
  return dropped_->first;
}

}  // namespace caustica
