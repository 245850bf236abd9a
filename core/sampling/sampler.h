#pragma once

#include <cstdint>
#include <memory>

#include "core/math/vec.h"
#include "core/registry/plugin.h"

namespace caustica {

// Random numbers for one sample of one pixel. Every value is a pure function
// of (seed, pixel, sample index, dimension), so an image does not depend on
// thread count or tile order, any sample can be replayed alone, and disjoint
// sample ranges rendered apart can be merged.
class Sampler : public Plugin {
 public:
  explicit Sampler(uint32_t sample_count) : sample_count_(sample_count) {}

  virtual std::unique_ptr<Sampler> clone() const = 0;
  virtual void start_sample(Vec2i pixel, uint64_t sample_index, uint64_t seed) = 0;
  virtual float next_1d() = 0;
  virtual Vec2 next_2d() = 0;

  uint32_t sample_count() const { return sample_count_; }
  void set_sample_count(uint32_t n) { sample_count_ = n; }

 private:
  uint32_t sample_count_;
};

}  // namespace caustica
