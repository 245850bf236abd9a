#pragma once

#include <string>

namespace caustica {

// Markdown tables of every registered plugin's parameters, derived from the
// declarations alone: a heading per category, a table per plugin (name,
// type, default, description). docs/plugins.md holds this text between its
// parameter markers; `caustica plugins` prints it.
std::string parameter_tables_markdown();

}  // namespace caustica
