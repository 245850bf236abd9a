// ldrfilm: Mitsuba 0.x's low-dynamic-range film. The render is developed
// into an 8-bit PNG or JPEG by the film's own settings: exposure, a tone
// mapping (gamma: none beyond the exposure; reinhard: Reinhard et al.'s
// global operator with key and burn) and a gamma curve (-1: sRGB's). The
// linear EXR is written beside it as for any film.
//
//   <film type="ldrfilm">
//       <integer name="width" value="512"/>
//       <float name="exposure" value="1"/>
//       <string name="tonemap_method" value="reinhard"/>
//   </film>

#include <cmath>

#include "core/film/film_settings.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

FilmOutput read_output(const Properties& props) {
  FilmOutput out;
  read_pixel_format(props, out, {"rgb", "rgba", "luminance", "luminance_alpha"});
  LdrDevelopment d;
  const std::string file = props.get_string("file_format");
  if (file != "png" && file != "jpeg") throw props.error("file_format", "must be png or jpeg, not '" + file + "'");
  d.jpeg = file == "jpeg";
  d.tonemap = props.get_string("tonemap_method");
  if (d.tonemap != "gamma" && d.tonemap != "reinhard")
    throw props.error("tonemap_method", "must be gamma or reinhard, not '" + d.tonemap + "'");
  d.gamma = props.get_float("gamma");
  if (!(d.gamma == -1 || (d.gamma > 0 && std::isfinite(d.gamma))))
    throw props.error("gamma", "must be positive, or -1 for sRGB's curve");
  d.exposure = props.get_float("exposure");
  if (!(std::abs(d.exposure) <= 100)) throw props.error("exposure", "must be between -100 and 100 stops");
  d.key = props.get_float("key");
  if (!(d.key > 0 && std::isfinite(d.key))) throw props.error("key", "must be positive");
  d.burn = props.get_float("burn");
  if (!(d.burn >= 0 && d.burn <= 1)) throw props.error("burn", "must be between 0 and 1");
  out.ldr = d;
  return out;
}

class LdrFilm final : public Film {
 public:
  explicit LdrFilm(const Properties& props) : Film(read_film_geometry(props), read_output(props)) {}
};

std::vector<ParamSpec> params() {
  auto p = film_geometry_params();
  p.insert(p.begin() + 2,
           {{"file_format", ParamType::String, "png", "png or jpeg: the developed image's format"},
            {"pixel_format", ParamType::String, "rgb",
             "rgb, rgba, luminance or luminance_alpha (the EXR's channels, as for hdrfilm)"},
            {"tonemap_method", ParamType::String, "gamma", "gamma (exposure only) or reinhard"},
            {"gamma", ParamType::Float, "-1", "display gamma, or -1 for sRGB's curve"},
            {"exposure", ParamType::Float, "0", "exposure in stops"},
            {"key", ParamType::Float, "0.18", "reinhard: where the log-average luminance lands"},
            {"burn", ParamType::Float, "0", "reinhard: 0 keeps highlights, 1 burns the brightest pixel to white"}});
  return p;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(LdrFilm, "film", "ldrfilm", CAUSTICA_UNITY_ID::params(), {"rfilter"});

}  // namespace caustica
