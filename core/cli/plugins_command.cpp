#include "core/cli/plugins_command.h"

#include <cstdio>

#include "core/registry/parameter_tables.h"

namespace caustica {

void PluginsCommand::add_to(CLI::App& app) {
  command_ = app.add_subcommand("plugins", "list every plugin's parameters (Markdown, as in docs/plugins.md)");
}

int PluginsCommand::run() const {
  std::fputs(parameter_tables_markdown().c_str(), stdout);
  return 0;
}

}  // namespace caustica
