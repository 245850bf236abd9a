#include "core/cli/merge_command.h"

#include <cstdio>
#include <filesystem>

#include "core/image/image_metrics.h"
#include "core/image/render_merge.h"
#include "core/job/merge_parts.h"
#include "core/job/range_merge.h"

namespace caustica {

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
  const RenderFile merged = merge_parts(std::move(parts));
  // Raw sums must stay exact, so a merge of sample ranges is written in float.
  bool half = exr_format_ == "half" && !has_raw_sums(merged);
  if (const size_t n = count_extreme_values(rows_of(merged.image)).beyond_half; half && n > 0) {
    half = false;
    std::fprintf(stderr, "caustica: note: %zu values exceed 65504, the largest half float: %s is written in float\n", n,
                 output_.c_str());
  }
  write_exr(output_, merged.image, merged.metadata, half);
  std::printf("%zu renders, %s spp -> %s", inputs_.size(), metadata_value(merged, "caustica:spp").c_str(),
              output_.c_str());
  if (const EstimatedError error = estimated_error(merged.image); error.known)
    std::printf(", estimated MSE %.4g, relative MSE %.4g", error.mse, error.rel_mse);
  std::printf("\n");
  return 0;
}

}  // namespace caustica
