#include "core/cli/merge_command.h"

#include <cstdio>
#include <filesystem>

#include "core/image/image_metrics.h"
#include "core/image/render_merge.h"
#include "core/job/range_merge.h"

namespace caustica {

namespace {

// Nine significant digits: errors are tiny numbers.
std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace

void MergeCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("merge",
                                "merge renders of a scene: independent ones (different seeds) by sample count, "
                                "disjoint --first-sample ranges of one seed (with --raw-sums) exactly");
  command_->add_option("inputs", inputs_, "EXRs written by caustica render")->required()->check(CLI::ExistingFile);
  command_->add_option("-o,--output", output_, "merged EXR")->required();
  command_->add_option("--exr-format", exr_format_, "half or float (default: float)")
      ->check(CLI::IsMember({"half", "float"}));
}

int MergeCommand::run() const {
  if (std::filesystem::path(output_).extension() != ".exr")
    throw std::invalid_argument("output must end in .exr: " + output_);
  std::vector<RenderFile> parts;
  for (const std::string& path : inputs_) parts.push_back(read_render(path));
  // Renders of one seed hold disjoint ranges of the same samples: their raw
  // sums add up exactly. Otherwise they are independent estimates.
  bool ranges = true;
  for (const RenderFile& part : parts)
    ranges = ranges && has_raw_sums(part) && render_seeds(part) == render_seeds(parts.front());
  if (!ranges)
    for (RenderFile& part : parts) part = without_raw_sums(std::move(part));
  RenderFile merged = ranges ? merge_sample_ranges(parts) : merge_renders(parts);
  // A reference carries its own error, so comparisons can discount it.
  const EstimatedError error = estimated_error(merged.image);
  if (error.known) {
    merged.metadata["caustica:estimated_mse"] = number_text(error.mse);
    merged.metadata["caustica:estimated_rel_mse"] = number_text(error.rel_mse);
  }
  bool half = exr_format_ == "half" && !ranges;
  if (const size_t n = count_extreme_values(rows_of(merged.image)).beyond_half; half && n > 0) {
    half = false;
    std::fprintf(stderr, "caustica: note: %zu values exceed 65504, the largest half float: %s is written in float\n", n,
                 output_.c_str());
  }
  write_exr(output_, merged.image, merged.metadata, half);
  std::printf("%zu renders, %s spp -> %s", parts.size(), merged.metadata["caustica:spp"].c_str(), output_.c_str());
  if (error.known) std::printf(", estimated MSE %.4g, relative MSE %.4g", error.mse, error.rel_mse);
  std::printf("\n");
  return 0;
}

}  // namespace caustica
