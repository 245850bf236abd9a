#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace caustica {

// `caustica info SCENE`: what the scene holds and what it needs simulated.
class InfoCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
  std::string scene_;
  std::vector<std::string> defines_;
};

}  // namespace caustica
