#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace caustica {

// `caustica merge IN.exr... -o OUT.exr`: independent renders of one scene
// (different seeds) merged by sample count into one, with its estimated
// error in the metadata (see merge_renders). Long references are rendered
// in chunks and merged with this.
class MergeCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
  std::vector<std::string> inputs_;
  std::string output_, exr_format_ = "float";
};

}  // namespace caustica
