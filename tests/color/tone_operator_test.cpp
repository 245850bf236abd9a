#include "core/color/tone_operator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

std::shared_ptr<ToneOperator> make(const std::string& name, std::vector<std::pair<std::string, double>> params = {}) {
  const PluginInfo* info = Registry::instance().find("tonemap", name);
  Properties props(*info, {"test", 1});
  for (const auto& [key, value] : params) props.set(key, {ValueKind::Float, value, {"test", 1}});
  return std::dynamic_pointer_cast<ToneOperator>(info->create(props));
}

std::vector<float> grey(std::vector<float> values) {
  std::vector<float> rgb;
  for (float v : values) rgb.insert(rgb.end(), {v, v, v});
  return rgb;
}

float apply_one(const ToneOperator& op, float v) {
  auto rgb = grey({v});
  op.apply(rgb);
  return rgb[0];
}

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

class EveryOperator : public testing::TestWithParam<std::string> {};

// Black stays black, the curve never decreases, and nothing unusual in the
// input (NaN, Inf, negative, huge) produces anything outside [0, 1].
TEST_P(EveryOperator, BlackMonotonicBoundedAndNanFree) {
  const auto op = make(GetParam());
  std::vector<float> ramp;
  for (int i = 0; i <= 400; ++i) ramp.push_back(std::pow(10.0f, -4 + i * 0.02f));  // 1e-4 .. 1e4
  auto rgb = grey(ramp);
  op->apply(rgb);
  for (size_t i = 3; i < rgb.size(); i += 3) EXPECT_GE(rgb[i], rgb[i - 3]) << GetParam() << " at " << ramp[i / 3];
  auto odd = grey({0, kNaN, kInf, -kInf, -1, 1e30f, std::numeric_limits<float>::max()});
  op->apply(odd);
  for (float v : odd) {
    EXPECT_TRUE(std::isfinite(v)) << GetParam();
    EXPECT_GE(v, 0) << GetParam();
    EXPECT_LE(v, 1) << GetParam();
  }
  EXPECT_NEAR(odd[0], 0, 1e-3f) << GetParam();
  EXPECT_EQ(odd[3], odd[0]) << GetParam() << ": NaN counts as black";
}

INSTANTIATE_TEST_SUITE_P(All, EveryOperator, testing::Values("none", "reinhard", "filmic", "aces"));

TEST(NoneTonemap, ClipsToUnitRange) {
  const auto op = make("none");
  EXPECT_EQ(apply_one(*op, 0.18f), 0.18f);
  EXPECT_EQ(apply_one(*op, 4.0f), 1.0f);
}

TEST(ReinhardTonemap, KeyValueAndWhitePoint) {
  // A uniform grey image: its log-average is itself, so every pixel lands on
  // the key, L = 0.18, and Ld = L (1 + L / white^2) / (1 + L).
  const auto plain = make("reinhard", {{"white", 1e30}});
  EXPECT_NEAR(apply_one(*plain, 0.5f), 0.18 / 1.18, 1e-5);
  const auto white = make("reinhard", {{"white", 0.18}});
  EXPECT_NEAR(apply_one(*white, 0.5f), 1.0, 1e-5);
  // White point 0 means the brightest pixel, which maps to exactly 1.
  auto rgb = grey({0.01f, 0.1f, 7.0f});
  make("reinhard")->apply(rgb);
  EXPECT_NEAR(rgb[6], 1.0f, 1e-6f);
  EXPECT_LT(rgb[3], rgb[6]);
}

// Burn b scales the brightest pixel's scaled luminance by (1 - b)^2 to get
// the white point: at b = 0.5, a pixel a quarter as bright as the brightest
// maps to exactly 1, and one an eighth as bright stays below it.
TEST(ReinhardTonemap, BurnMovesTheWhitePointDown) {
  auto rgb = grey({0.125f, 0.25f, 1.0f});
  make("reinhard", {{"burn", 0.5}})->apply(rgb);
  EXPECT_NEAR(rgb[3], 1.0f, 1e-5f);
  EXPECT_LT(rgb[0], 0.99f);
}

TEST(ReinhardTonemap, KeepsHue) {
  // (Where a channel would exceed 1 it is clipped, which shifts hue; a far
  // white point keeps every channel below 1 here.)
  std::vector<float> rgb = {0.4f, 0.2f, 0.1f, 0.05f, 0.05f, 0.05f};
  make("reinhard", {{"white", 1e30}})->apply(rgb);
  EXPECT_NEAR(rgb[0] / rgb[1], 2.0f, 1e-5f);
  EXPECT_NEAR(rgb[1] / rgb[2], 2.0f, 1e-5f);
}

TEST(FilmicTonemap, MiddleGreyAndWhite) {
  const auto op = make("filmic");
  // f(2 * 0.18) / f(11.2) with Hable's constants, evaluated by hand.
  EXPECT_NEAR(apply_one(*op, 0.18f), 0.128338449, 1e-6);
  EXPECT_NEAR(apply_one(*op, 11.2f / 2), 1.0, 1e-6);
  EXPECT_EQ(apply_one(*op, 0), 0);
}

TEST(AcesTonemap, MiddleGreyAndHighlights) {
  const auto op = make("aces");
  // ACES 1.0 SDR-video places scene middle grey near 10% of display white.
  EXPECT_NEAR(apply_one(*op, 0.18f), 0.10, 0.03);
  EXPECT_GT(apply_one(*op, 16.0f), 0.75f);
  EXPECT_LE(apply_one(*op, 1e4f), 1.0f);
}

// An image with black pixels, developed: every operator's output against
// its formula worked out by the test. Black pixels enter Reinhard's
// log-average through its offset delta = 1e-6 (log(delta + Lw)); without
// it one black pixel sends the log-average to zero and every other pixel to
// white. The per-pixel operators give each pixel what it gets alone.
const std::vector<float> kWithBlack = {0, 0,    0,    0.05f, 0.05f, 0.05f, 0.3f, 0.3f, 0.3f, 0, 0,
                                       0, 0.9f, 0.4f, 0.1f,  2,     2,     2,    6,    6,    6};

double rec709_luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

TEST(EveryOperatorFormula, ReinhardWithBlackPixels) {
  const size_t n = kWithBlack.size() / 3;
  double log_sum = 0, largest = 0;
  for (size_t p = 0; p < n; ++p)
    log_sum += std::log(1e-6 + rec709_luminance(kWithBlack[3 * p], kWithBlack[3 * p + 1], kWithBlack[3 * p + 2]));
  const double scale = 0.18 / std::exp(log_sum / double(n));
  for (size_t p = 0; p < n; ++p)
    largest =
        std::max(largest, scale * rec709_luminance(kWithBlack[3 * p], kWithBlack[3 * p + 1], kWithBlack[3 * p + 2]));
  std::vector<float> rgb = kWithBlack;
  make("reinhard")->apply(rgb);
  for (size_t p = 0; p < n; ++p) {
    const double lw = rec709_luminance(kWithBlack[3 * p], kWithBlack[3 * p + 1], kWithBlack[3 * p + 2]);
    const double l = scale * lw, ld = l * (1 + l / (largest * largest)) / (1 + l);
    for (int c = 0; c < 3; ++c) {
      const double expected = lw > 0 ? std::min(1.0, kWithBlack[3 * p + c] * ld / lw) : 0.0;
      EXPECT_NEAR(rgb[3 * p + c], expected, 1e-5) << "pixel " << p << " channel " << c;
    }
  }
  EXPECT_LT(rgb[3], 0.5f) << "a dark pixel stays dark beside black ones";
}

TEST(EveryOperatorFormula, FilmicWithBlackPixels) {
  const auto hable = [](double x) {
    return (x * (0.15 * x + 0.05) + 0.004) / (x * (0.15 * x + 0.5) + 0.06) - 0.02 / 0.3;
  };
  std::vector<float> rgb = kWithBlack;
  make("filmic")->apply(rgb);
  for (size_t i = 0; i < rgb.size(); ++i)
    EXPECT_NEAR(rgb[i], std::min(1.0, hable(2.0 * kWithBlack[i]) / hable(11.2)), 1e-6) << i;
}

TEST(EveryOperatorFormula, NoneWithBlackPixels) {
  std::vector<float> rgb = kWithBlack;
  make("none")->apply(rgb);
  for (size_t i = 0; i < rgb.size(); ++i) EXPECT_EQ(rgb[i], std::min(1.0f, kWithBlack[i])) << i;
}

// ACES is OpenColorIO's own transform: per pixel, so black pixels beside
// them change nothing, and black stays black.
TEST(EveryOperatorFormula, AcesWithBlackPixelsIsPerPixel) {
  const auto op = make("aces");
  std::vector<float> rgb = kWithBlack;
  op->apply(rgb);
  for (size_t p = 0; p < kWithBlack.size() / 3; ++p) {
    std::vector<float> alone(kWithBlack.begin() + long(3 * p), kWithBlack.begin() + long(3 * p + 3));
    op->apply(alone);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(rgb[3 * p + c], alone[c]) << p;
  }
  EXPECT_NEAR(rgb[0], 0, 1e-3f);
}

TEST(ToneOperator, ExposureIsAParameter) {
  EXPECT_EQ(make("filmic", {{"exposure", 1.5}})->exposure(), 1.5f);
  EXPECT_EQ(make("none")->exposure(), 0.0f);
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
