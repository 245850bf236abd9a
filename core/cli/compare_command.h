#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "core/image/image_metrics.h"

namespace caustica {

// `caustica compare IMAGE.exr REFERENCE.exr [--epsilon E]`: the error of a
// render against a reference, one "name value" line per metric (see
// ErrorMetrics), for people and for the convergence benchmarks alike.
class CompareCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
  std::string image_, reference_;
  double epsilon_ = kRelMseEpsilon;
};

}  // namespace caustica
