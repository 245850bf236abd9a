#include "core/cli/compare_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/cli/number_checks.h"
#include "core/image/image_input.h"
#include "core/image/render_merge.h"

namespace caustica {

void CompareCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("compare", "print the error of a render against a reference (MSE, relMSE, MAE)");
  command_->add_option("image", image_, "EXR to judge")->required()->check(CLI::ExistingFile);
  command_->add_option("reference", reference_, "reference EXR, ideally with variance layers")
      ->required()
      ->check(CLI::ExistingFile);
  command_->add_option("--epsilon", epsilon_, "relative MSE is (x - ref)^2 / (ref^2 + epsilon)")
      ->check(finite_positive());
}

int CompareCommand::run() const {
  require_linear_image(image_);
  require_linear_image(reference_);
  const RenderFile image = read_render(image_), reference = read_render(reference_);
  // Shared samples would make the render and the reference err alike, and
  // the comparison would understate the render's error.
  const std::vector<std::string> reference_seeds = render_seeds(reference);
  for (const std::string& seed : render_seeds(image))
    if (std::find(reference_seeds.begin(), reference_seeds.end(), seed) != reference_seeds.end())
      std::fprintf(stderr,
                   "caustica: warning: '%s' and the reference '%s' share seed %s: their errors are correlated, and "
                   "the error is understated\n",
                   image_.c_str(), reference_.c_str(), seed.c_str());

  const ErrorMetrics m = compare_images(image.image, reference.image, epsilon_);
  const auto known = [](const EstimatedError& e, double v) { return e.known ? v : NAN; };
  const std::pair<const char*, double> lines[] = {
      {"mse", m.mse},
      {"mse_corrected", m.mse_corrected},
      {"rel_mse", m.rel_mse},
      {"rel_mse_corrected", m.rel_mse_corrected},
      {"mae", m.mae},
      {"reference_estimated_mse", known(m.reference, m.reference.mse)},
      {"reference_estimated_rel_mse", known(m.reference, m.reference.rel_mse)},
      {"estimated_mse", known(m.image, m.image.mse)},
      {"estimated_rel_mse", known(m.image, m.image.rel_mse)},
  };
  for (const auto& [name, value] : lines) std::printf("%s %.9g\n", name, value);
  return 0;
}

}  // namespace caustica
