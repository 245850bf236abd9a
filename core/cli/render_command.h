#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "core/cli/develop_options.h"

namespace caustica {

// `caustica render SCENE [-o OUT.exr] [--spp N | --time S] ...`
class RenderCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  int replay(const class RenderJob& job) const;

  CLI::App* command_ = nullptr;
  std::string scene_, output_, integrator_, debug_pixel_, exr_format_;
  std::vector<std::string> defines_;
  uint32_t spp_ = 0;
  double time_ = 0;
  int threads_ = 0;
  uint64_t seed_ = 0, debug_sample_ = 0, first_sample_ = 0;
  bool quiet_ = false, raw_sums_ = false;
  DevelopOptions develop_;
};

}  // namespace caustica
