#include "core/job/replay_command.h"

#include <algorithm>
#include <string_view>

namespace caustica {

namespace {
namespace CAUSTICA_UNITY_ID {

std::string shell_quoted(const std::string& arg) {
  const bool plain = !arg.empty() && std::all_of(arg.begin(), arg.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string_view("_-=:,./+@%").find(c) != std::string_view::npos;
  });
  if (plain) return arg;
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::string replay_command(const std::string& scene, const std::vector<std::string>& defines,
                           const RenderSettings& settings, SampleId id) {
  std::string command = "caustica render " + shell_quoted(scene);
  for (const std::string& define : defines) command += " -D " + shell_quoted(define);
  if (!settings.integrator.empty()) command += " --integrator " + shell_quoted(settings.integrator);
  if (settings.spp > 0) command += " --spp " + std::to_string(settings.spp);
  command += " --seed " + std::to_string(settings.seed);
  if (settings.transport == RenderSettings::Transport::Spectral) command += " --spectral on";
  if (settings.transport == RenderSettings::Transport::Rgb) command += " --spectral off";
  if (settings.light_selection == RenderSettings::LightSelection::Tree) command += " --light-selection tree";
  if (settings.light_selection == RenderSettings::LightSelection::Power) command += " --light-selection power";
  return command + " --debug-pixel " + std::to_string(id.pixel.x) + "," + std::to_string(id.pixel.y) +
         " --debug-sample " + std::to_string(id.index);
}

}  // namespace caustica
