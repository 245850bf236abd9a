#include "integrators/bidirectional/primary_sample_space.h"

#include <cmath>

#include "core/sampling/pcg32.h"

namespace caustica {

PrimarySampleSpace::PrimarySampleSpace(uint64_t seed, uint64_t chain, float sigma)
    : Sampler(1), rng_(mix_bits(seed ^ mix_bits(chain + 0x9e3779b97f4a7c15ULL)), chain), sigma_(sigma) {}

void PrimarySampleSpace::reseed(uint64_t seed, uint64_t chain) {
  rng_.seed(mix_bits(seed ^ mix_bits(chain + 0x632be59bd9b4e019ULL)), chain);
}

void PrimarySampleSpace::start_stream(int stream) {
  stream_ = stream;
  read_ = 0;
}

float PrimarySampleSpace::next_1d() {
  const size_t i = size_t(stream_) + kStreams * read_++;
  if (i >= numbers_.size()) numbers_.resize(i + 1);
  Number& x = numbers_[i];
  bring_up_to_date(x);
  return x.value;
}

Vec2 PrimarySampleSpace::next_2d() {
  const float u = next_1d();
  return {u, next_1d()};
}

void PrimarySampleSpace::mutate(bool large) {
  ++step_;
  large_ = large;
  saved_large_ = last_large_;
  if (large) last_large_ = step_;
}

void PrimarySampleSpace::accept() {}

// The numbers read in the rejected step go back to what they were, and
// the step is undone, so that numbers read later take no offset for it.
void PrimarySampleSpace::reject() {
  for (Number& x : numbers_)
    if (x.updated == step_) {
      x.value = x.saved;
      x.updated = x.saved_updated;
    }
  last_large_ = saved_large_;
  --step_;
}

void PrimarySampleSpace::bring_up_to_date(Number& x) {
  if (x.updated == step_) return;
  x.saved = x.value;
  x.saved_updated = x.updated;
  if (large_ && last_large_ == step_) {
    x.value = rng_.next_float();
  } else {
    // Not read since before the last large step: its value there was a
    // fresh one, which it takes now.
    if (x.updated < last_large_) {
      x.value = rng_.next_float();
      x.updated = last_large_;
    }
    // Box-Muller; 1 - u keeps the logarithm finite.
    const float u1 = 1 - rng_.next_float(), u2 = rng_.next_float();
    const float normal = std::sqrt(-2 * std::log(u1)) * std::cos(6.2831853f * u2);
    const float moved = x.value + normal * sigma_ * std::sqrt(float(step_ - x.updated));
    x.value = moved - std::floor(moved);
    if (!(x.value < 1)) x.value = 0;
  }
  x.updated = step_;
}

}  // namespace caustica
