// aces: the ACES 1.0 output transform for SDR video (RRT + ODT, 100 nits),
// through OpenColorIO's built-in transforms, so it matches any other ACES
// pipeline. Scene-linear Rec.709 goes to ACEScg, to ACES2065-1, through the
// output transform to display-linear CIE XYZ (D65), and back to Rec.709
// primaries for the display view to encode. ACES brings its own tone scale
// and gamut mapping; use it with the Standard view (the config's ACES view
// already contains the same transform, for use with tonemap none).
//
//   <tonemap type="aces"/>

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>

#include "core/color/tone_operator.h"
#include "core/registry/properties.h"

namespace OCIO = OCIO_NAMESPACE;

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

OCIO::ConstCPUProcessorRcPtr make_aces_processor() {
  auto group = OCIO::GroupTransform::Create();
  const auto builtin = [&](const char* style, OCIO::TransformDirection direction) {
    auto t = OCIO::BuiltinTransform::Create();
    t->setStyle(style);
    t->setDirection(direction);
    group->appendTransform(t);
  };
  builtin("UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", OCIO::TRANSFORM_DIR_INVERSE);
  builtin("ACEScg_to_ACES2065-1", OCIO::TRANSFORM_DIR_FORWARD);
  builtin("ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0", OCIO::TRANSFORM_DIR_FORWARD);
  // CIE XYZ (D65) to linear Rec.709 (IEC 61966-2-1).
  const double xyz_to_rec709[16] = {3.2409699, -1.5373832, -0.4986108, 0, -0.9692436, 1.8759675, 0.0415551, 0,
                                    0.0556301, -0.2039770, 1.0569715,  0, 0,          0,         0,         1};
  auto matrix = OCIO::MatrixTransform::Create();
  matrix->setMatrix(xyz_to_rec709);
  group->appendTransform(matrix);
  return OCIO::Config::CreateRaw()->getProcessor(group)->getDefaultCPUProcessor();
}

class AcesTonemap final : public ToneOperator {
 public:
  explicit AcesTonemap(const Properties& props) : ToneOperator(props), processor_(make_aces_processor()) {}

  void apply(std::vector<float>& rgb) const override {
    for (float& v : rgb) v = sanitize_radiance(v);
    if (rgb.empty()) return;
    OCIO::PackedImageDesc desc(rgb.data(), long(rgb.size() / 3), 1, 3);
    processor_->apply(desc);
    // The output transform's gamut mapping leaves saturated primaries
    // slightly outside [0, 1].
    for (float& v : rgb) v = std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f);
  }

 private:
  OCIO::ConstCPUProcessorRcPtr processor_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(AcesTonemap, "tonemap", "aces", tone_operator_params({}), {});

}  // namespace caustica
