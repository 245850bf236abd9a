#pragma once

#include <cstdint>
#include <memory>

#include "core/math/vec.h"
#include "core/registry/plugin.h"

namespace caustica {

class Properties;

// The independent families of samples a render draws. Each stream has its
// own keys: a camera sample and a light path are keyed by their pixel, a
// photon by its round.
enum class SampleStream : uint32_t { CameraPixel = 0, LightPath = 1, PhotonRound = 2 };

// Which sequence of samples start_sample() selects: the stream, and a key
// within it (a pixel or a round number).
struct SampleKey {
  SampleStream stream;
  uint64_t key;

  static SampleKey pixel(SampleStream stream, Vec2i p) {
    return {stream, (uint64_t(uint32_t(p.y)) << 32) | uint32_t(p.x)};
  }
  static SampleKey camera(Vec2i p) { return pixel(SampleStream::CameraPixel, p); }
  static SampleKey light_path(Vec2i p) { return pixel(SampleStream::LightPath, p); }
  static SampleKey photon_round(uint64_t round) { return {SampleStream::PhotonRound, round}; }
};

// Random numbers for one sample. Every value is a pure function of (seed,
// stream, key, sample index, dimension), so an image does not depend on
// thread count or tile order, any sample can be replayed alone, and disjoint
// sample ranges rendered apart can be merged.
class Sampler : public Plugin {
 public:
  explicit Sampler(uint32_t sample_count) : sample_count_(sample_count) {}

  virtual std::unique_ptr<Sampler> clone() const = 0;
  // Starts sample `index` of the sequence `key` at dimension 0.
  virtual void start_sample(SampleKey key, uint64_t index, uint64_t seed) = 0;
  virtual float next_1d() = 0;
  virtual Vec2 next_2d() = 0;

  uint32_t sample_count() const { return sample_count_; }

 private:
  uint32_t sample_count_;
};

// The sample_count parameter every sampler declares: a positive 32-bit count.
uint32_t read_sample_count(const Properties& props);

}  // namespace caustica
