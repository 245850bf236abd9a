// bitmap: a colour image read from a file (PNG, JPEG, EXR, HDR, ... through
// OpenImageIO), looked up at the surface's (u, v).
//
// Orientation (as Mitsuba 3): u runs left to right and v top to bottom, so
// (0, 0) is the image's top-left corner. Meshes whose files follow the
// v-up convention (OBJ) are flipped on load by the shape's flip_tex_coords.
//
// Colour: unless `raw`, images stored as integers (8- or 16-bit PNG, JPEG)
// are taken as sRGB-encoded and decoded to linear values with the sRGB
// transfer function (IEC 61966-2-1); floating-point images (EXR, HDR) are
// linear already and used as stored. One channel (grey) gives grey colours;
// with two channels the second (alpha) is ignored, and from four or more
// the first three are used as RGB. `channel` (Mitsuba 0.x's) instead makes
// a grey texture of one named channel, e.g. "a"; alpha is never decoded.
// mean() is the average over the pixels.
//
// Outside [0, 1], `wrap_mode` repeats, mirrors or clamps the image, or reads
// zero or one everywhere (0.x's "zero" and "one"); `wrap_mode_u` and
// `wrap_mode_v` set either axis apart, as 0.x's wrapModeU and wrapModeV.
//
//   <texture type="bitmap" name="reflectance">
//       <string name="filename" value="textures/wood.png"/>
//       <string name="wrap_mode" value="mirror"/>
//   </texture>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <vector>

#include "core/color/srgb_transfer.h"
#include "core/files/input_file.h"
#include "core/image/image_limits.h"
#include "core/math/transform.h"
#include "core/registry/properties.h"
#include "core/texture/texture.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

enum class WrapMode { Repeat, Mirror, Clamp, Zero, One };

// A pixel index, possibly outside [0, n), mapped into it; -1 where the
// mode reads a constant there instead.
int wrap(int i, int n, WrapMode mode) {
  switch (mode) {
    case WrapMode::Zero:
    case WrapMode::One:
      return i >= 0 && i < n ? i : -1;
    case WrapMode::Clamp:
      return std::clamp(i, 0, n - 1);
    case WrapMode::Mirror: {
      int m = i % (2 * n);
      if (m < 0) m += 2 * n;
      return m < n ? m : 2 * n - 1 - m;
    }
    case WrapMode::Repeat:
    default: {
      const int m = i % n;
      return m < 0 ? m + n : m;
    }
  }
}

// A pixel coordinate from a texture coordinate, kept in int range so that
// the wrap arithmetic cannot overflow for absurd uv.
float pixel_coordinate(float t, int n) { return std::clamp(t * float(n), -1e8f, 1e8f); }

class BitmapTexture final : public Texture {
 public:
  explicit BitmapTexture(const Properties& props) {
    const std::filesystem::path file = props.get_path("filename");
    const std::string filter = props.get_string("filter_type");
    if (filter == "bilinear")
      bilinear_ = true;
    else if (filter == "nearest")
      bilinear_ = false;
    else
      throw props.error("filter_type", "unknown filter '" + filter + "' (accepted: bilinear, nearest)");
    const WrapMode both = wrap_mode(props, "wrap_mode");
    wrap_u_ = props.has("wrap_mode_u") ? wrap_mode(props, "wrap_mode_u") : both;
    wrap_v_ = props.has("wrap_mode_v") ? wrap_mode(props, "wrap_mode_v") : both;
    if (props.has("to_uv")) to_uv_ = props.get_transform("to_uv");
    if (props.has("format")) props.warn("format", "is ignored: caustica keeps textures in float");
    if (props.has("accel")) props.warn("accel", "is ignored: it concerns GPU texture units");
    load(props, file, props.get_bool("raw"), props.has("channel") ? props.get_string("channel") : "");
  }

  Color eval(Vec2 uv) const override {
    if (to_uv_) {
      const Vec3 p = to_uv_->point({uv.x, uv.y, 0});
      uv = {p.x, p.y};
    }
    const float x = pixel_coordinate(uv.x, width_), y = pixel_coordinate(uv.y, height_);
    if (!std::isfinite(x) || !std::isfinite(y)) return {};
    if (!bilinear_) return texel(int(std::floor(x)), int(std::floor(y)));
    // Pixel centres lie at half-integer coordinates.
    const float fx = x - 0.5f, fy = y - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float tx = fx - x0, ty = fy - y0;
    const int ix = int(x0), iy = int(y0);
    return (texel(ix, iy) * (1 - tx) + texel(ix + 1, iy) * tx) * (1 - ty) +
           (texel(ix, iy + 1) * (1 - tx) + texel(ix + 1, iy + 1) * tx) * ty;
  }

  static WrapMode wrap_mode(const Properties& props, const std::string& name) {
    const std::string mode = props.get_string(name);
    if (mode == "repeat") return WrapMode::Repeat;
    if (mode == "mirror") return WrapMode::Mirror;
    if (mode == "clamp") return WrapMode::Clamp;
    if (mode == "zero") return WrapMode::Zero;
    if (mode == "one") return WrapMode::One;
    throw props.error(name, "unknown wrap mode '" + mode + "' (accepted: repeat, mirror, clamp, zero, one)");
  }

  Color mean() const override { return mean_; }
  std::optional<Vec2i> resolution() const override { return Vec2i{width_, height_}; }
  ValueRange range() const override { return range_; }

 private:
  void load(const Properties& props, const std::filesystem::path& file, bool raw, const std::string& channel) {
    if (const std::string problem = input_file_problem(file); !problem.empty())
      throw props.error("filename", "image file '" + file.string() + "' " + problem);
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw props.error("filename", "cannot read image '" + file.string() + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (channels <= 0) throw props.error("filename", "image '" + file.string() + "' has no channels");
    if (const std::string problem = image_size_problem(spec.width, spec.height); !problem.empty())
      throw props.error("filename", "image '" + file.string() + "': " + problem);
    std::vector<float> data(size_t(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data()))
      throw props.error("filename", "cannot read image '" + file.string() + "': " + in->geterror());
    const OIIO::TypeDesc::BASETYPE base = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
    const bool is_float =
        base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::DOUBLE;
    bool decode = !raw && !is_float;
    int only = -1;  // the one channel `channel` names
    if (!channel.empty()) {
      const auto lower = [](std::string t) {
        for (char& c : t) c = char(std::tolower(static_cast<unsigned char>(c)));
        return t;
      };
      std::string names;
      for (int c = 0; c < channels; ++c) {
        const std::string name = c < int(spec.channelnames.size()) ? spec.channelnames[c] : std::to_string(c);
        if (lower(name) == lower(channel)) only = c;
        names += (c ? ", " : "") + name;
      }
      if (only < 0)
        throw props.error("channel",
                          "image '" + file.string() + "' has no channel '" + channel + "' (it has " + names + ")");
      if (only == spec.alpha_channel || lower(channel) == "a" || lower(channel) == "alpha") decode = false;
    }

    width_ = spec.width;
    height_ = spec.height;
    pixels_.resize(size_t(width_) * height_);
    range_ = {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
    double sum[3] = {};
    for (size_t i = 0; i < pixels_.size(); ++i) {
      const float* p = &data[i * channels];
      Color c = only >= 0 ? Color(p[only]) : channels >= 3 ? Color(p[0], p[1], p[2]) : Color(p[0]);
      if (decode) c = {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)};
      if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
        throw props.error("filename", "image '" + file.string() + "' has a pixel that is not finite, at (" +
                                          std::to_string(i % size_t(width_)) + ", " +
                                          std::to_string(i / size_t(width_)) + ")");
      pixels_[i] = c;
      for (int k = 0; k < 3; ++k) sum[k] += c[k];
      range_.lowest = std::min({range_.lowest, c.r, c.g, c.b});
      range_.highest = std::max({range_.highest, c.r, c.g, c.b});
    }
    const double n = double(pixels_.size());
    mean_ = {float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
  }

  Color texel(int x, int y) const {
    const int i = wrap(x, width_, wrap_u_), j = wrap(y, height_, wrap_v_);
    if (i < 0) return Color(wrap_u_ == WrapMode::One ? 1.0f : 0.0f);
    if (j < 0) return Color(wrap_v_ == WrapMode::One ? 1.0f : 0.0f);
    return pixels_[size_t(j) * width_ + i];
  }

  int width_ = 0, height_ = 0;
  std::vector<Color> pixels_;  // linear RGB, top row first
  Color mean_;
  ValueRange range_;
  bool bilinear_ = true;
  WrapMode wrap_u_ = WrapMode::Repeat, wrap_v_ = WrapMode::Repeat;
  std::optional<Transform> to_uv_;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(
    BitmapTexture, "texture", "bitmap",
    {{"filename", ParamType::String, std::nullopt, "image file, relative to the scene file"},
     {"filter_type", ParamType::String, "bilinear", "bilinear or nearest"},
     {"wrap_mode", ParamType::String, "repeat",
      "what (u, v) outside [0, 1]^2 read: repeat, mirror, clamp, zero or one"},
     {"wrap_mode_u", ParamType::String, std::nullopt, "wrap_mode along u alone (optional; Mitsuba 0.x's wrapModeU)"},
     {"wrap_mode_v", ParamType::String, std::nullopt, "wrap_mode along v alone (optional; Mitsuba 0.x's wrapModeV)"},
     {"channel", ParamType::String, std::nullopt,
      "a grey texture of this one channel of the image, by name, e.g. r or a (optional; Mitsuba 0.x's)"},
     {"raw", ParamType::Boolean, "false", "use stored values without sRGB decoding"},
     {"to_uv", ParamType::Transform, std::nullopt, "applied to (u, v, 0) before the lookup (optional)"},
     {"format", ParamType::String, std::nullopt, "accepted and ignored (textures are kept in float)"},
     {"accel", ParamType::Boolean, std::nullopt, "accepted and ignored (GPU texture units)"}},
    {});

}  // namespace caustica
