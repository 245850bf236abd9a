#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "core/math/exact_sum.h"
#include "core/math/vec.h"

namespace caustica {

class ReconstructionFilter;
class SplatList;

// Where a sample that was dropped came from, so it can be replayed.
struct SampleId {
  Vec2i pixel;
  uint64_t index = 0;
};

// Per-pixel accumulation of filter-weighted samples over named channels,
// with (where asked) the moments of the first three (the beauty) for
// variance estimates, plus
// an optional splat image for contributions that land on other pixels than
// their sample's. This is the one place samples enter an image: NaN and Inf
// are dropped and counted here, never averaged in.
class FilmBuffer {
 public:
  // Whether the film keeps the moments behind variance(): the beauty does;
  // the first-hit layers, whose variance nobody reads, need not hold them.
  enum class Moments { Kept, None };
  FilmBuffer(int width, int height, std::vector<std::string> channels, Moments moments = Moments::Kept);

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<std::string>& channels() const { return channels_; }
  size_t channel_count() const { return channels_.size(); }

  // Safe to call concurrently for different pixels. `samples` is how many
  // samples the values stand for: 1, except for an iterative estimator's
  // per-pixel estimate after as many iterations.
  void add_sample(SampleId id, std::span<const float> values, float weight, uint32_t samples = 1);

  // Makes room for the splat image; call before splats arrive.
  void enable_splats();
  // Adds the splats that fall on rows [y_begin, y_end), each spread over
  // the pixels in the filter's reach with weights f(dx) f(dy) normalised to
  // integrate to one. Calls for disjoint row ranges may run concurrently;
  // splats reach each pixel in list order, so sums do not depend on threads.
  void add_splats(const SplatList& list, const ReconstructionFilter& filter, int y_begin, int y_end);
  // Counts the list's dropped splats; call once per list.
  void record_dropped(const SplatList& list);
  // Counts n more light paths per pixel: the splat image is divided by
  // their total.
  void add_splat_paths(uint64_t n) { splat_paths_per_pixel_ += n; }
  bool has_splats() const { return !splat_sum_.empty(); }

  // The weighted mean of each channel plus the splat image, pixel-interleaved.
  std::vector<float> resolve() const;
  // The same for one pixel (index y * width + x): channel_count() values.
  void resolve_pixel(size_t pixel, float* out) const;
  // Per-pixel variance of the weighted mean of the beauty channels,
  // estimated from the samples as sum w^2 (x - mean)^2 / (sum w)^2 with the
  // n / (n - 1) correction; pixel-interleaved, three per pixel. Splats are
  // not part of it. Only for a film that keeps its moments.
  std::vector<float> variance() const;
  void variance_pixel(size_t pixel, float* out) const;
  bool keeps_moments() const { return !moments_.empty(); }
  uint32_t sample_count(Vec2i pixel) const { return count_[index(pixel)]; }

  // The sums behind resolve() and variance() as float channels named
  // prefix + "sum.R.0" ..., for storing a render so that renders of
  // disjoint sample ranges merge into the film of one render of them all.
  // Each sum becomes six floats: three (.0, .1, .2) adding up to its value,
  // three (.3, .4, .5) to its rest (an ExactSum's; 0 for a moment) scaled by
  // 2^64, exactly for magnitudes between 1e-24 and 1e35; the sample count is
  // one channel. The beauty's sums are exact, so merged films equal the film
  // of all their samples bit for bit, but for the variance (see moments_).
  std::vector<std::string> raw_channels(const std::string& prefix) const;
  // Pixel-interleaved, raw_channels().size() values per pixel.
  std::vector<float> export_raw() const;
  void export_raw_pixel(size_t pixel, float* out) const;
  // Adds sums export_raw() gave for a film of the same size and channels;
  // `splat_paths` is the light paths per pixel behind its splats.
  void add_raw(std::span<const float> raw, uint64_t splat_paths);

  // Adds everything `other` holds, a film of the same size, channels and
  // moments: the result is the film of both films' samples (bit for bit but
  // for the variance's moments).
  void add(const FilmBuffer& other);
  // Back to no samples, keeping the memory (and the splat image, if any).
  void clear();

  // Everything the film holds (sums, counts, splat paths, dropped samples)
  // as doubles, for another process to add to a film of the same size,
  // channels and moments with add_packed: the result is the film of both
  // films' samples, as add() makes it.
  std::vector<double> pack() const;
  // Throws std::invalid_argument when `packed` does not fit this film.
  void add_packed(std::span<const double> packed);

  uint64_t dropped_samples() const { return dropped_->count.load(); }
  // The first dropped sample (lowest pixel, then index), if any.
  SampleId first_dropped() const;

 private:
  size_t index(Vec2i p) const { return size_t(p.y) * width_ + p.x; }

  int width_, height_;
  std::vector<std::string> channels_;
  // Exact sums, so that no order or grouping of the samples changes a bit.
  std::vector<ExactSum> weighted_sum_;  // channels per pixel
  std::vector<ExactSum> weight_sum_;
  // The variance's sums of w^2, w^2 x and w^2 x^2 (three each) are plain
  // doubles: exact ones would cost 56 more bytes a pixel, and a variance
  // estimate gains nothing from its last bit. Merged films' variances so
  // agree with one render's to rounding, not bit for bit.
  struct MomentSums {
    double w2 = 0, w2x[3] = {}, w2x2[3] = {};
  };
  std::vector<MomentSums> moments_;  // per pixel; empty without moments
  std::vector<uint32_t> count_;
  std::vector<ExactSum> splat_sum_;  // channels per pixel, allocated by the first splat
  uint64_t splat_paths_per_pixel_ = 0;
  // The sums of one pixel in the order raw_channels() names them.
  template <class Self, class F>
  static void for_each_sum(Self& film, size_t p, F&& f);
  struct DropLog {
    std::atomic<uint64_t> count{0};
    std::mutex mutex;
    SampleId first{{-1, -1}, 0};
    void record(SampleId id, uint64_t count);
  };
  std::unique_ptr<DropLog> dropped_ = std::make_unique<DropLog>();
};

}  // namespace caustica
