// hdrfilm: a linear, high-dynamic-range film written as OpenEXR.
//
// A nested rfilter (box, tent or gaussian) reconstructs the pixels from the
// samples; without one it is a gaussian with its default parameters.
//
//   <film type="hdrfilm">
//       <integer name="width" value="512"/>
//       <integer name="height" value="512"/>
//       <rfilter type="tent"/>
//   </film>

#include "core/film/film.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {

std::shared_ptr<ReconstructionFilter> filter_or_default(const Properties& props) {
  if (auto f = props.child<ReconstructionFilter>("rfilter")) return f;
  return Registry::instance().create_default<ReconstructionFilter>("rfilter", "gaussian", props.where());
}

int positive(const Properties& props, const char* name) {
  const int64_t v = props.get_int(name);
  if (v <= 0 || v > 1 << 16) throw props.error(name, "must be between 1 and 65536");
  return int(v);
}

class HdrFilm final : public Film {
  // 8192 x 8192; the accumulation buffers take about 100 bytes a pixel.
  static constexpr int64_t kMaxPixels = int64_t(1) << 26;

 public:
  explicit HdrFilm(const Properties& props)
      : Film(positive(props, "width"), positive(props, "height"), filter_or_default(props), half(props)) {
    if (int64_t(width()) * height() > kMaxPixels)
      throw props.error("height", "width x height must be at most " + std::to_string(kMaxPixels) + " pixels");
    const std::string format = props.get_string("pixel_format");
    if (format != "rgb" && format != "rgba") throw props.error("pixel_format", "must be rgb or rgba");
  }

 private:
  static bool half(const Properties& props) {
    const std::string f = props.get_string("component_format");
    if (f != "float16" && f != "float32") throw props.error("component_format", "must be float16 or float32");
    return f == "float16";
  }
};

}  // namespace

CAUSTICA_REGISTER_PLUGIN(HdrFilm, "film", "hdrfilm",
                         {{"width", ParamType::Integer, "768", "width in pixels"},
                          {"height", ParamType::Integer, "576", "height in pixels"},
                          {"pixel_format", ParamType::String, "rgb",
                           "rgb or rgba (rgba is accepted, but no alpha channel is written)"},
                          {"component_format", ParamType::String, "float16", "float16 or float32"}},
                         {"rfilter"});

}  // namespace caustica
