// caustica: the command line. See docs/user-guide.md for the commands.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>

#include "core/cli/compare_command.h"
#include "core/cli/info_command.h"
#include "core/cli/merge_command.h"
#include "core/cli/plugins_command.h"
#include "core/cli/render_command.h"
#include "core/cli/tonemap_command.h"
#include "core/color/display_transform.h"
#include "core/color/rgb_spectrum_table.h"
#include "core/errors/interrupted.h"
#include "core/version.h"

int main(int argc, char** argv) {
  CLI::App app{"caustica: a physically based Monte Carlo renderer"};
  // The version, and where this binary finds its data: an installed one
  // in its prefix's share/caustica, one in the build tree beside the build.
  app.set_version_flag("--version", [] {
    return std::string("caustica ") + caustica::kVersion +
           "\nRGB-to-spectrum table: " + caustica::RgbSpectrumTable::built_path().string() +
           "\nOCIO config: " + caustica::default_ocio_config().string();
  });
  app.require_subcommand(1);
  caustica::RenderCommand render;
  render.add_to(app);
  caustica::InfoCommand info;
  info.add_to(app);
  caustica::TonemapCommand tonemap;
  tonemap.add_to(app);
  caustica::MergeCommand merge;
  merge.add_to(app);
  caustica::CompareCommand compare;
  compare.add_to(app);
  caustica::PluginsCommand plugins;
  plugins.add_to(app);
  CLI11_PARSE(app, argc, argv);
  try {
    if (render.chosen()) return render.run();
    if (info.chosen()) return info.run();
    if (tonemap.chosen()) return tonemap.run();
    if (merge.chosen()) return merge.run();
    if (compare.chosen()) return compare.run();
    if (plugins.chosen()) return plugins.run();
  } catch (const caustica::Interrupted&) {
    std::cerr << "caustica: interrupted before anything was rendered\n";
    return 130;
  } catch (const std::exception& e) {
    std::cerr << "caustica: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
