#pragma once

#include <cstdint>
#include <span>

#include "core/math/color.h"
#include "core/render/path_settings.h"
#include "core/scene/scene.h"

namespace caustica {

// The second speed round's experiment: `path` on surfaces (no media, RGB)
// advanced a bounce at a time over a batch of paths, each wave traced
// together (in Embree's packets of 16, or one ray at a time) and then
// shaded path by path. Every path draws the same numbers and does the same
// arithmetic in the same order as trace_path, so its radiance is the
// scalar walk's, bit for bit; what differs is only the order of the work.
struct CameraSampleKey {
  Vec2i pixel;
  uint64_t index;
};

// The radiance of each camera sample by the scalar walk (trace_path), one
// after another on one sampler.
void trace_scalar(const Scene& scene, const PathSettings& settings, uint64_t seed,
                  std::span<const CameraSampleKey> samples, std::span<Color> out);

// The same by the batched walk: batches of `batch` paths, each wave's rays
// traced `packet` (1 or 16) at a time.
void trace_batched(const Scene& scene, const PathSettings& settings, uint64_t seed,
                   std::span<const CameraSampleKey> samples, size_t batch, int packet, std::span<Color> out);

}  // namespace caustica
