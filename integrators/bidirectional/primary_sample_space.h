#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/sampling/pcg32.h"
#include "core/sampling/sampler.h"

namespace caustica {

// The random numbers of one Markov chain in primary sample space (Kelemen
// et al. 2002): a sampler whose numbers are the chain's state, changed by
// mutations and kept or restored as the chain accepts or rejects them.
// A large step draws every number afresh; a small step moves each by a
// normal offset of standard deviation `sigma`, wrapped into [0, 1), a
// symmetric proposal. Numbers are made when first read and brought up to
// date lazily: one read after n small steps moves it by the sum of n
// offsets, a single normal of deviation sigma sqrt(n).
//
// The numbers are split into streams (the camera subpath, the light
// subpath, the connection), interleaved so that each stream's numbers stay
// the same however many another stream reads: number i of stream j is
// dimension j + kStreams i.
class PrimarySampleSpace final : public Sampler {
 public:
  static constexpr int kStreams = 3;

  // The chain's own random numbers come from (seed, chain).
  PrimarySampleSpace(uint64_t seed, uint64_t chain, float sigma);

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<PrimarySampleSpace>(*this); }
  // Restarts the read position of every stream (the key and index are the
  // chain's, not the caller's).
  void start_sample(SampleKey, uint64_t, uint64_t) override { start_stream(0); }
  float next_1d() override;
  Vec2 next_2d() override;

  // Reads from stream `stream` from its first number on.
  void start_stream(int stream);
  // Proposes the next state: every number afresh (large) or moved.
  void mutate(bool large);
  // Keeps the proposed state, or restores the one before it.
  void accept();
  void reject();
  // A number from the chain's own generator, apart from the state.
  float uniform() { return rng_.next_float(); }
  // Gives the chain a generator of its own from (seed, chain), apart from
  // the one that made its state (a chain started from a bootstrap state
  // goes on with its own numbers).
  void reseed(uint64_t seed, uint64_t chain);

 private:
  struct Number {
    float value = 0, saved = 0;
    uint64_t updated = 0, saved_updated = 0;  // the step it was brought up to date at
  };
  void bring_up_to_date(Number& x);

  Pcg32 rng_;
  float sigma_;
  std::vector<Number> numbers_;
  uint64_t step_ = 0, last_large_ = 0, saved_large_ = 0;
  bool large_ = true;
  int stream_ = 0;
  uint64_t read_ = 0;
};

}  // namespace caustica
