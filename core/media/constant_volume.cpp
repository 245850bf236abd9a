// constvolume: the same value everywhere.
//
//   <volume type="constvolume" name="albedo">
//       <rgb name="value" value="0.9, 0.8, 0.7"/>
//   </volume>

#include "core/media/constant_volume.h"

#include <cmath>

#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class ConstantVolume final : public Volume {
 public:
  explicit ConstantVolume(const Properties& props) : ConstantVolume(props.get_color("value")) {
    for (int c = 0; c < 3; ++c)
      if (!(value_[c] >= 0) || !std::isfinite(value_[c]))
        throw props.error("value", "must be finite and at least 0 in every channel");
  }
  explicit ConstantVolume(Color value) : value_(value) {}

  Color eval(Vec3) const override { return value_; }
  bool is_constant() const override { return true; }
  bool is_chromatic() const override { return !(value_.r == value_.g && value_.g == value_.b); }
  float max_in(const Bounds3&) const override { return value_.max_component(); }
  Vec3 local(Vec3 p) const override { return p; }
  Vec3 local_vector(Vec3 v) const override { return v; }

 private:
  Color value_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::shared_ptr<const Volume> make_constant_volume(Color value) { return std::make_shared<ConstantVolume>(value); }

CAUSTICA_REGISTER_PLUGIN(ConstantVolume, "volume", "constvolume",
                         {{"value", ParamType::Color, "1", "the value everywhere, per channel"}}, {});

}  // namespace caustica
