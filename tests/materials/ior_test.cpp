#include "core/bsdf/ior.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// A stand-in plugin declaration, to read IOR parameters as a material would.
const PluginInfo kInfo{"bsdf", "ior_reader", {{"int_ior", ParamType::Ior, "bk7", ""}}, {}, nullptr, {}};

float read(const PropertyValue& v) {
  Properties props(kInfo, {"test.xml", 1});
  props.set("int_ior", v);
  return read_ior(props, "int_ior");
}

TEST(Ior, NumbersAndNames) {
  EXPECT_FLOAT_EQ(read_ior(Properties(kInfo, {"test.xml", 1}), "int_ior"), 1.5046f);
  EXPECT_FLOAT_EQ(read({ValueKind::Float, 1.33, {"test.xml", 2}}), 1.33f);
  EXPECT_FLOAT_EQ(read({ValueKind::String, std::string("water"), {"test.xml", 2}}), 1.333f);
  EXPECT_FLOAT_EQ(read({ValueKind::String, std::string("1.7"), {"test.xml", 2}}), 1.7f);
  EXPECT_FLOAT_EQ(*named_ior("diamond"), 2.419f);
}

TEST(Ior, BadValuesNameTheLine) {
  EXPECT_THAT(
      [] {
        read({ValueKind::String, std::string("glass"), {"test.xml", 4}});
      },
      testing::ThrowsMessage<SceneError>(testing::HasSubstr(
          "test.xml:4: parameter 'int_ior' of bsdf 'ior_reader': unknown index of refraction 'glass' (known: "
          "vacuum")));
  for (const double bad : {0.0, -1.5})
    EXPECT_THAT(
        [bad] {
          read({ValueKind::Float, bad, {"test.xml", 5}});
        },
        testing::ThrowsMessage<SceneError>(testing::HasSubstr("must be positive")));
}

// Mitsuba takes any positive index (an air bubble's interior in ice is 0.763
// relative to the ice around it).
TEST(Ior, IndicesBelowOneAreAccepted) { EXPECT_FLOAT_EQ(read({ValueKind::Float, 0.763, {"test.xml", 5}}), 0.763f); }

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
