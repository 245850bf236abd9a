#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/cli/develop_options.h"
#include "core/job/distributed_render.h"

namespace caustica {

// `caustica render SCENE [-o OUT.exr] [--spp N | --time S] ...`
class RenderCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  int render(const RankSession* session) const;
  int replay(const RenderJob& job) const;
  // Under mpirun, on rank 0 once the image is written (`render`'s result
  // now moved out): a render that lost ranks or was signalled ends the job
  // with a message saying what the image holds.
  void end_distributed(const DistributedRender& render, const RenderStats& stats, const RankSession& session,
                       const std::filesystem::path& exr) const;

  CLI::App* command_ = nullptr;
  std::string scene_, output_, integrator_, debug_pixel_, exr_format_, spectral_ = "auto", light_selection_ = "auto";
  std::vector<std::string> defines_;
  uint32_t spp_ = 0;
  double time_ = 0, rank_timeout_ = 120;
  int threads_ = 0;
  uint64_t seed_ = 0, debug_sample_ = 0, first_sample_ = 0;
  bool quiet_ = false, raw_sums_ = false;
  DevelopOptions develop_;
};

}  // namespace caustica
