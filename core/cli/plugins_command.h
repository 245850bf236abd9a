#pragma once

#include <CLI/CLI.hpp>

namespace caustica {

// `caustica plugins`: every plugin's parameters as Markdown tables, the
// text of docs/plugins.md.
class PluginsCommand {
 public:
  void add_to(CLI::App& app);
  bool chosen() const { return command_ && command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_ = nullptr;
};

}  // namespace caustica
