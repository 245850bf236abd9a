// Spectra become linear Rec.709 as Mitsuba's RGB variants make them: the
// CIE 1931 integral over that of y, then Rec.709's primaries. The expected
// values are properties of the colour spaces and published figures, not
// re-computations: a flat spectrum is equal-energy (X = Y = Z), D65 is
// Rec.709's white, Wien's displacement law, and the Cornell box's measured
// reflectances give the RGB Mitsuba's own Cornell box scene (its
// tutorials' cbox.xml) publishes for them: white 0.885809, 0.698859,
// 0.666422; red 0.570068, 0.0430135, 0.0443706; green 0.105421, 0.37798,
// 0.076425.

#include "core/color/spectrum_to_rgb.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/color/cie_tables.h"
#include "tests/support/thrown_message.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

using ::testing::HasSubstr;

const std::string kCornellWhite =
    "400:0.343, 404:0.445, 408:0.551, 412:0.624, 416:0.665, 420:0.687, 424:0.708, 428:0.723, "
    "432:0.715, 436:0.71, 440:0.745, 444:0.758, 448:0.739, 452:0.767, 456:0.777, 460:0.765, "
    "464:0.751, 468:0.745, 472:0.748, 476:0.729, 480:0.745, 484:0.757, 488:0.753, 492:0.75, "
    "496:0.746, 500:0.747, 504:0.735, 508:0.732, 512:0.739, 516:0.734, 520:0.725, 524:0.721, "
    "528:0.733, 532:0.725, 536:0.732, 540:0.743, 544:0.744, 548:0.748, 552:0.728, 556:0.716, "
    "560:0.733, 564:0.726, 568:0.713, 572:0.74, 576:0.754, 580:0.764, 584:0.752, 588:0.736, "
    "592:0.734, 596:0.741, 600:0.74, 604:0.732, 608:0.745, 612:0.755, 616:0.751, 620:0.744, "
    "624:0.731, 628:0.733, 632:0.744, 636:0.731, 640:0.712, 644:0.708, 648:0.729, 652:0.73, "
    "656:0.727, 660:0.707, 664:0.703, 668:0.729, 672:0.75, 676:0.76, 680:0.751, 684:0.739, "
    "688:0.724, 692:0.73, 696:0.74, 700:0.737";

const std::string kCornellRed =
    "400:0.04, 404:0.046, 408:0.048, 412:0.053, 416:0.049, 420:0.05, 424:0.053, 428:0.055, "
    "432:0.057, 436:0.056, 440:0.059, 444:0.057, 448:0.061, 452:0.061, 456:0.06, 460:0.062, "
    "464:0.062, 468:0.062, 472:0.061, 476:0.062, 480:0.06, 484:0.059, 488:0.057, 492:0.058, "
    "496:0.058, 500:0.058, 504:0.056, 508:0.055, 512:0.056, 516:0.059, 520:0.057, 524:0.055, "
    "528:0.059, 532:0.059, 536:0.058, 540:0.059, 544:0.061, 548:0.061, 552:0.063, 556:0.063, "
    "560:0.067, 564:0.068, 568:0.072, 572:0.08, 576:0.09, 580:0.099, 584:0.124, 588:0.154, "
    "592:0.192, 596:0.255, 600:0.287, 604:0.349, 608:0.402, 612:0.443, 616:0.487, 620:0.513, "
    "624:0.558, 628:0.584, 632:0.62, 636:0.606, 640:0.609, 644:0.651, 648:0.612, 652:0.61, 656:0.65, "
    "660:0.638, 664:0.627, 668:0.62, 672:0.63, 676:0.628, 680:0.642, 684:0.639, 688:0.657, "
    "692:0.639, 696:0.635, 700:0.642";

const std::string kCornellGreen =
    "400:0.092, 404:0.096, 408:0.098, 412:0.097, 416:0.098, 420:0.095, 424:0.095, 428:0.097, "
    "432:0.095, 436:0.094, 440:0.097, 444:0.098, 448:0.096, 452:0.101, 456:0.103, 460:0.104, "
    "464:0.107, 468:0.109, 472:0.112, 476:0.115, 480:0.125, 484:0.14, 488:0.16, 492:0.187, "
    "496:0.229, 500:0.285, 504:0.343, 508:0.39, 512:0.435, 516:0.464, 520:0.472, 524:0.476, "
    "528:0.481, 532:0.462, 536:0.447, 540:0.441, 544:0.426, 548:0.406, 552:0.373, 556:0.347, "
    "560:0.337, 564:0.314, 568:0.285, 572:0.277, 576:0.266, 580:0.25, 584:0.23, 588:0.207, "
    "592:0.186, 596:0.171, 600:0.16, 604:0.148, 608:0.141, 612:0.136, 616:0.13, 620:0.126, "
    "624:0.123, 628:0.121, 632:0.122, 636:0.119, 640:0.114, 644:0.115, 648:0.117, 652:0.117, "
    "656:0.118, 660:0.12, 664:0.122, 668:0.128, 672:0.132, 676:0.139, 680:0.144, 684:0.146, "
    "688:0.15, 692:0.152, 696:0.157, 700:0.159";

void expect_rgb(Color c, double r, double g, double b, double tolerance) {
  EXPECT_NEAR(c.r, r, tolerance);
  EXPECT_NEAR(c.g, g, tolerance);
  EXPECT_NEAR(c.b, b, tolerance);
}

// Back to XYZ by Rec.709's published matrix (IEC 61966-2-1).
void expect_xyz(Color c, double x, double y, double z, double tolerance) {
  EXPECT_NEAR(0.4124564 * c.r + 0.3575761 * c.g + 0.1804375 * c.b, x, tolerance);
  EXPECT_NEAR(0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b, y, tolerance);
  EXPECT_NEAR(0.0193339 * c.r + 0.1191920 * c.g + 0.9503041 * c.b, z, tolerance);
}

TEST(SpectrumToRgb, AFlatSpectrumIsEqualEnergy) {
  expect_xyz(spectrum_to_rgb(parse_spectrum_pairs("360:0.5, 830:0.5")), 0.5, 0.5, 0.5, 2e-3);
  expect_xyz(spectrum_to_rgb(parse_spectrum_pairs("360:3, 830:3")), 3, 3, 3, 1e-2);
}

TEST(SpectrumToRgb, D65IsWhite) {
  SampledSpectrum d65;
  for (int i = 0; i < kCieSamples; ++i) {
    d65.nm.push_back(kCieFirstNm + i * kCieStepNm);
    d65.values.push_back(kCieD65[size_t(i)]);
  }
  const Color c = spectrum_to_rgb(d65);
  EXPECT_NEAR(c.r / c.g, 1, 2e-3);
  EXPECT_NEAR(c.b / c.g, 1, 2e-3);
}

TEST(SpectrumToRgb, TheCornellBoxSpectraGiveTheirPublishedRgb) {
  expect_rgb(spectrum_to_rgb(parse_spectrum_pairs(kCornellWhite)), 0.885809, 0.698859, 0.666422, 1e-3);
  expect_rgb(spectrum_to_rgb(parse_spectrum_pairs(kCornellRed)), 0.570068, 0.0430135, 0.0443706, 1e-3);
  expect_rgb(spectrum_to_rgb(parse_spectrum_pairs(kCornellGreen)), 0.105421, 0.37798, 0.076425, 1e-3);
}

// Wien: the peak lies at 2.897771955e-3 m K / T.
TEST(SpectrumToRgb, ABlackBodyPeaksWhereWienSays) {
  for (const double kelvin : {4000.0, 5000.0, 6000.0}) {
    const SampledSpectrum s = blackbody(kelvin);
    const auto peak = std::max_element(s.values.begin(), s.values.end()) - s.values.begin();
    EXPECT_NEAR(s.nm[size_t(peak)], 2.897771955e6 / kelvin, 2.5) << kelvin;
  }
  // Hotter is bluer.
  const Color warm = spectrum_to_rgb(blackbody(3000));
  const Color cool = spectrum_to_rgb(blackbody(9000));
  EXPECT_GT(warm.r / warm.b, cool.r / cool.b);
}

TEST(SpectrumToRgb, BadSpectraAreRefusedWithTheReason) {
  const auto error = [](const std::string& text) {
    return test::thrown_message<std::invalid_argument>([&] { parse_spectrum_pairs(text); });
  };
  EXPECT_EQ(error("400:0.3, 390:0.4"), "wavelengths must increase, but 390.000000 nm follows 400.000000 nm");
  EXPECT_EQ(error("400:0.3, 500-0.4"), "expected wavelength:value, got ' 500-0.4'");
  EXPECT_EQ(error("400:abc"), "cannot read 'abc' as a value");
  EXPECT_EQ(error("400:1e999"), "cannot read '1e999' as a value");
  EXPECT_EQ(error("-5:1"), "wavelength -5.000000 nm is not positive");
}

TEST(SpectrumToRgb, SpdFilesAreReadWithCommentsAndLinesNamed) {
  const auto dir = std::filesystem::temp_directory_path();
  std::ofstream(dir / "flat.spd") << "# a flat spectrum\n360 0.25\n\n830\t0.25  # end\n";
  expect_xyz(spectrum_to_rgb(read_spd_file(dir / "flat.spd")), 0.25, 0.25, 0.25, 1e-3);
  std::ofstream(dir / "bad.spd") << "360 0.25\n400 0.3\n420 x\n";
  try {
    read_spd_file(dir / "bad.spd");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("bad.spd:3: cannot read 'x' as a value"));
  }
}

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
