#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image/image_output.h"

namespace caustica {

// A render as `caustica render` writes it: its image and metadata, and the
// file it came from (for messages).
struct RenderFile {
  std::string path;
  Image image;
  std::map<std::string, std::string> metadata;
};

// Reads a render's EXR with its metadata.
RenderFile read_render(const std::string& path);

// An error about a render, naming its file: "'PATH' problem".
std::invalid_argument render_error(const RenderFile& render, const std::string& problem);

// A metadata value, or "" if the render has none.
std::string metadata_value(const RenderFile& render, const std::string& key);
// A metadata value that must be a number; throws naming the file if not.
double metadata_number(const RenderFile& render, const std::string& key);
// Throws std::invalid_argument naming `part` unless it has the size,
// channels, scene and integrator of `first`.
void check_same_render(const RenderFile& first, const RenderFile& part);

// The seeds a render's samples came from: its caustica:seed, or for a merged
// render the list in caustica:seeds. Empty if the metadata names none.
std::vector<std::string> render_seeds(const RenderFile& render);

// Merges independent renders of one scene and integrator (different seeds)
// into one estimate, weighting each pixel of each render by the samples it
// holds (samples.Y, or the spp metadata where that layer is absent):
//   mean = sum n_i x_i / N and, since the renders are independent,
//   variance of the mean = sum n_i^2 v_i / N^2, with N = sum n_i.
// Every channel but variance.* and samples.Y is merged as a mean. The film
// weights samples by its filter rather than by count; the difference is of
// order 1/n and vanishes as the renders grow.
// Metadata: the first render's, with spp, seconds, samples and rays summed,
// the seeds listed in caustica:seeds, and interrupted if any part was.
// Throws std::invalid_argument naming the file when sizes, channels, scene or
// integrator differ, or when two renders share a seed (the same samples).
RenderFile merge_renders(const std::vector<RenderFile>& parts);

}  // namespace caustica
