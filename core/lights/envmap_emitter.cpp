// envmap: an environment given by a latitude-longitude image (EXR, HDR, PNG,
// ... through OpenImageIO), y up as in Mitsuba: the image's top row looks
// along +y, its left edge along -z, its centre column along +z, and u grows
// with atan2(x, -z).
// Each texel's radiance is constant over it; directions are sampled in
// proportion to luminance times sin(theta), the texels' solid angle.
//
//   <emitter type="envmap">
//       <string name="filename" value="sky.exr"/>
//       <float name="scale" value="2"/>
//       <transform name="to_world"><rotate y="1" angle="90"/></transform>
//   </emitter>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "core/image/image_input.h"
#include "core/lights/emitter.h"
#include "core/lights/scene_disk.h"
#include "core/math/constants.h"
#include "core/math/frame.h"
#include "core/registry/properties.h"
#include "core/sampling/piecewise_constant_2d.h"
#include "core/sampling/warp.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

class EnvmapEmitter final : public Emitter {
 public:
  explicit EnvmapEmitter(const Properties& props) {
    // Only the rotation matters to directions; the render origin's
    // translation falls out of vector().
    to_world_ = props.get_transform("to_world");
    to_local_ = to_world_.inverse();
    const float scale = props.get_float("scale");
    if (!(scale >= 0 && std::isfinite(scale))) throw props.error("scale", "must be finite and not negative");
    const auto file = props.get_path("filename");
    Image image;
    try {
      image = read_image(file);
    } catch (const std::exception& e) {
      throw props.error("filename", e.what());
    }
    width_ = image.width;
    height_ = image.height;
    const size_t channels = image.channels.size();
    const bool grey = channels < 3;
    texels_.resize(size_t(width_) * height_);
    std::vector<float> weights(texels_.size());
    for (int y = 0; y < height_; ++y) {
      const float sin_theta = std::sin((float(y) + 0.5f) * kPi / float(height_));
      for (int x = 0; x < width_; ++x) {
        const size_t i = size_t(y) * width_ + x;
        const float* p = &image.pixels[i * channels];
        const Color v = grey ? Color(p[0]) : Color(p[0], p[1], p[2]), c = v * scale;
        const auto at = [&] { return " at pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"; };
        // Channel by channel: a finite 3e38 in each would overflow their sum.
        for (const float channel : {v.r, v.g, v.b})
          if (!std::isfinite(channel) || channel < 0)
            throw props.error("filename", "'" + file.string() + "' has a negative or non-finite value" + at());
        for (const float channel : {c.r, c.g, c.b})
          if (!std::isfinite(channel)) {
            char text[160];
            std::snprintf(text, sizeof text, "times %g overflows single precision%s (its value there is %g)",
                          double(scale), at().c_str(), double(std::max({v.r, v.g, v.b})));
            throw props.error("scale", "'" + file.string() + "' " + text + "; express the scene in other units");
          }
        texels_[i] = c;
        weights[i] = c.luminance() * sin_theta;
      }
    }
    for (int y = 0; y < height_; ++y) {
      // The solid angle of a texel of row y.
      const double omega = (2 * M_PI / width_) * (std::cos(M_PI * y / height_) - std::cos(M_PI * (y + 1) / height_));
      for (int x = 0; x < width_; ++x) radiant_ += texels_[size_t(y) * width_ + x] * float(omega);
    }
    // Relative to the largest, so that rows of radiance near float's limit
    // do not overflow the distribution's sums.
    const float largest = *std::max_element(weights.begin(), weights.end());
    if (largest > 0) {
      for (float& w : weights) w /= largest;
      distribution_.emplace(weights, width_, height_);
    }
  }

  void prepare(const Bounds3& bounds) override { disk_.fit(bounds); }

  std::optional<LiSample> sample_Li(const ReferencePoint& ref, Vec2 u) const override {
    if (!distribution_) return std::nullopt;
    float pdf_uv = 0;
    const Vec2 uv = distribution_->sample(u, &pdf_uv);
    const Vec3 wi = to_world_direction(uv);
    // The density pdf_Li gives for wi, so that MIS weights agree exactly.
    const float pdf = pdf_direction(wi);
    if (!(pdf > 0)) return std::nullopt;
    return LiSample{wi, texel(uv), pdf, false, ref.p + wi * disk_.beyond(), {}, {}, true};
  }

  float pdf_Li(const ReferencePoint&, Vec3 wi, const SurfaceInteraction&) const override { return pdf_direction(wi); }

  Color Le_infinite(Vec3 d, float) const override { return texel(to_uv(d)); }

  std::optional<LeSample> sample_Le(Vec2 u_pos, Vec2 u_dir, float) const override {
    if (!distribution_) return std::nullopt;
    float pdf_uv = 0;
    const Vec2 uv = distribution_->sample(u_dir, &pdf_uv);
    const Vec3 d = -to_world_direction(uv);
    const float pdf_dir = pdf_direction(-d);
    if (!(pdf_dir > 0)) return std::nullopt;
    return LeSample{{disk_.origin(d, u_pos), d, kInfinity}, {}, texel(uv), disk_.pdf(), pdf_dir, {}};
  }

  void pdf_Le(const Ray& ray, Vec3, float* pdf_pos, float* pdf_dir) const override {
    *pdf_pos = disk_.pdf();
    *pdf_dir = pdf_direction(-ray.d);
  }

  // Radiance times the solid angle of each texel, through the disk.
  Color power() const override { return radiant_ * disk_.area(); }
  bool is_infinite() const override { return true; }

 private:
  // The direction (toward the environment) of a point of the image.
  Vec3 to_world_direction(Vec2 uv) const {
    const float phi = uv.x * 2 * kPi, theta = uv.y * kPi;
    const float sin_theta = std::sin(theta);
    return normalize(to_world_.vector({std::sin(phi) * sin_theta, std::cos(theta), -std::cos(phi) * sin_theta}));
  }
  Vec2 to_uv(Vec3 d_world) const {
    const Vec3 d = normalize(to_local_.vector(d_world));
    float u = std::atan2(d.x, -d.z) * kInv2Pi;
    if (u < 0) u += 1;
    // theta from atan2: accurate near the poles, where acos is not.
    return {u, std::atan2(std::sqrt(d.x * d.x + d.z * d.z), d.y) * kInvPi};
  }
  Color texel(Vec2 uv) const {
    const int x = std::clamp(int(uv.x * float(width_)), 0, width_ - 1);
    const int y = std::clamp(int(uv.y * float(height_)), 0, height_ - 1);
    return texels_[size_t(y) * width_ + x];
  }
  // A density over the image's [0,1)^2 as one over solid angle:
  // d omega = 2 pi^2 sin(theta) du dv.
  float pdf_direction(Vec3 wi) const {
    if (!distribution_) return 0;
    const Vec3 d = normalize(to_local_.vector(wi));
    const float sin_theta = std::sqrt(d.x * d.x + d.z * d.z);
    return sin_theta > 0 ? distribution_->pdf(to_uv(wi)) / (2 * kPi * kPi * sin_theta) : 0;
  }

  Transform to_world_, to_local_;
  int width_ = 0, height_ = 0;
  std::vector<Color> texels_;
  std::optional<PiecewiseConstant2D> distribution_;
  Color radiant_;  // radiance integrated over the sphere
  SceneDisk disk_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(EnvmapEmitter, "emitter", "envmap",
                         {{"filename", ParamType::String, std::nullopt,
                           "latitude-longitude image, relative to the scene file"},
                          {"scale", ParamType::Float, "1", "factor on the image's radiance"},
                          {"to_world", ParamType::Transform, "", "rotation of the environment"}},
                         {});

}  // namespace caustica
