// The replay command a render prints for its first dropped sample names
// every option the sample depends on, quoted for a shell where needed.

#include "core/job/replay_command.h"

#include <gtest/gtest.h>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

TEST(ReplayCommand, NamesEveryOptionTheSampleDependsOn) {
  RenderSettings settings;
  settings.integrator = "bdpt:rr_depth=1";
  settings.spp = 256;
  settings.seed = 1;
  settings.threads = 2;
  settings.first_sample = 64;
  settings.transport = RenderSettings::Transport::Spectral;
  EXPECT_EQ(replay_command("scenes/cornell-box-fog.xml", {"res=48", "sampler=independent"}, settings, {{20, 26}, 136}),
            "caustica render scenes/cornell-box-fog.xml -D res=48 -D sampler=independent --integrator "
            "bdpt:rr_depth=1 --spp 256 --seed 1 --spectral on --debug-pixel 20,26 --debug-sample 136");
  settings.transport = RenderSettings::Transport::Rgb;
  EXPECT_NE(replay_command("a.xml", {}, settings, {{0, 0}, 0}).find(" --spectral off "), std::string::npos);
}

TEST(ReplayCommand, LeavesOutWhatTheSceneDecides) {
  RenderSettings settings;
  settings.time_limit = 10;
  EXPECT_EQ(replay_command("box.xml", {}, settings, {{3, 4}, 5}),
            "caustica render box.xml --seed 0 --debug-pixel 3,4 --debug-sample 5");
}

TEST(ReplayCommand, QuotesArgumentsAShellWouldSplit) {
  EXPECT_EQ(replay_command("my scenes/Bob's box.xml", {"name=a b", "empty="}, RenderSettings{}, {{1, 2}, 3}),
            "caustica render 'my scenes/Bob'\\''s box.xml' -D 'name=a b' -D empty= --seed 0 --debug-pixel 1,2 "
            "--debug-sample 3");
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
