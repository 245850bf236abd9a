#include "core/color/display_transform.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

const std::filesystem::path kConfig = std::string(CAUSTICA_SOURCE_DIR) + "/core/color/config.ocio";

float through(const DisplayTransform& t, float v) {
  std::vector<float> rgb = {v, v, v};
  t.apply(rgb, 1, 1);
  return rgb[0];
}

TEST(ShippedConfig, PassesOcioCheck) {
  const std::string cmd = "ociocheck --iconfig " + kConfig.string() + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  EXPECT_EQ(pclose(pipe), 0) << out;
  EXPECT_NE(out.find("Validation **\npassed"), std::string::npos) << out;
  EXPECT_EQ(out.find("ERROR"), std::string::npos) << out;
}

// IEC 61966-2-1: 12.92 v below 0.0031308, 1.055 v^(1/2.4) - 0.055 above.
TEST(ShippedConfig, StandardViewIsTheSrgbCurve) {
  const DisplayTransform standard(kConfig, "", "");
  EXPECT_EQ(standard.display(), "sRGB");
  EXPECT_EQ(standard.view(), "Standard");
  EXPECT_NEAR(through(standard, 0.0f), 0.0f, 1e-6f);
  EXPECT_NEAR(through(standard, 0.0031308f), 0.0404500f, 2e-5f);
  EXPECT_NEAR(through(standard, 0.18f), 0.4613561f, 2e-5f);
  EXPECT_NEAR(through(standard, 0.5f), 0.7353570f, 2e-5f);
  EXPECT_NEAR(through(standard, 1.0f), 1.0f, 2e-5f);
}

TEST(ShippedConfig, RawAcesViewsAndLook) {
  EXPECT_FLOAT_EQ(through(DisplayTransform(kConfig, "sRGB", "Raw"), 0.3f), 0.3f);
  const float aces = through(DisplayTransform(kConfig, "sRGB", "ACES"), 0.18f);
  EXPECT_GT(aces, 0.25f);  // display-encoded middle grey
  EXPECT_LT(aces, 0.45f);
  // The "Bright" look doubles scene values (one stop) before the view.
  EXPECT_NEAR(through(DisplayTransform(kConfig, "sRGB", "Standard", "Bright"), 0.09f), 0.4613561f, 2e-5f);
  EXPECT_THROW(DisplayTransform(kConfig, "sRGB", "Standard", "sepia"), std::runtime_error);
  EXPECT_THROW(DisplayTransform(kConfig, "sRGB", "Filmic"), std::runtime_error);
}

std::string error_of(const std::string& display, const std::string& view, const std::string& look = "") {
  try {
    DisplayTransform(kConfig, display, view, look);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// An unknown display, view or look is named with what the config has.
TEST(ShippedConfig, UnknownNamesListWhatTheConfigHas) {
  const std::string config = "OpenColorIO config '" + kConfig.string() + "': ";
  EXPECT_EQ(error_of("P3", ""), config + "no display named 'P3' (it has sRGB)");
  EXPECT_EQ(error_of("sRGB", "Filmic"),
            config + "display 'sRGB' has no view named 'Filmic' (it has Standard, ACES, Raw)");
  EXPECT_EQ(error_of("", "Filmic"), config + "display 'sRGB' has no view named 'Filmic' (it has Standard, ACES, Raw)");
  EXPECT_EQ(error_of("sRGB", "Standard", "sepia"), config + "no look named 'sepia' (it has Bright)");
}

// A studio's config named by $OCIO replaces the shipped one.
TEST(OcioEnvironment, OverridesTheShippedConfig) {
  const auto path = std::filesystem::temp_directory_path() / "caustica_studio.ocio";
  std::ofstream(path) << R"(ocio_profile_version: 2
roles:
  default: lin
  scene_linear: lin
displays:
  Studio:
    - !<View> {name: Half, colorspace: half}
colorspaces:
  - !<ColorSpace> {name: lin}
  - !<ColorSpace>
    name: half
    from_scene_reference: !<MatrixTransform> {matrix: [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1]}
)";
  const char* previous = std::getenv("OCIO");
  setenv("OCIO", path.c_str(), 1);
  EXPECT_EQ(default_ocio_config(), path);
  const DisplayTransform studio(default_ocio_config(), "", "");
  EXPECT_EQ(studio.display(), "Studio");
  EXPECT_FLOAT_EQ(through(studio, 0.8f), 0.4f);
  if (previous)
    setenv("OCIO", previous, 1);
  else
    unsetenv("OCIO");
  EXPECT_EQ(default_ocio_config(), kConfig);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
