#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "core/cli/develop_options.h"

namespace caustica {

// `caustica tonemap IN.exr -o OUT.png [--exposure EV] [--tonemap NAME] ...`:
// develops a finished render again without rendering it again.
class TonemapCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
  std::string input_, output_;
  DevelopOptions develop_;
};

}  // namespace caustica
