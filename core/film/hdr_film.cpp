// hdrfilm: a linear, high-dynamic-range film, written as OpenEXR (or, as
// file_format asks, Radiance RGBE or PFM).
//
// A nested rfilter (box, tent or gaussian) reconstructs the pixels from the
// samples; without one it is a gaussian with its default parameters. A crop
// window renders only part of the film, seen as the whole film would see it.
//
//   <film type="hdrfilm">
//       <integer name="width" value="512"/>
//       <integer name="height" value="512"/>
//       <rfilter type="tent"/>
//   </film>

#include "core/film/film_settings.h"
#include "core/registry/properties.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

FilmOutput read_output(const Properties& props) {
  FilmOutput out;
  const std::string file = props.get_string("file_format");
  if (file == "openexr" || file == "exr")
    out.file = FileFormat::OpenExr;
  else if (file == "rgbe")
    out.file = FileFormat::Rgbe;
  else if (file == "pfm")
    out.file = FileFormat::Pfm;
  else
    throw props.error("file_format", "must be openexr, rgbe or pfm, not '" + file + "'");
  read_pixel_format(props, out, {"rgb", "rgba", "luminance", "luminance_alpha", "xyz", "xyza"});

  const std::string component = props.get_string("component_format");
  if (component != "float16" && component != "float32" && component != "uint32")
    throw props.error("component_format", "must be float16, float32 or uint32, not '" + component + "'");
  out.half_float = component == "float16";
  if (component == "uint32")
    props.warn("component_format", "uint32 is written as float32: integers would truncate the radiance");
  if (out.file != FileFormat::OpenExr && props.has("component_format") && component != "float32")
    props.warn("component_format", "RGBE and PFM files hold their own formats; this has no effect");
  return out;
}

class HdrFilm final : public Film {
 public:
  explicit HdrFilm(const Properties& props) : Film(read_film_geometry(props), read_output(props)) {}
};

std::vector<ParamSpec> params() {
  auto p = film_geometry_params();
  p.insert(p.begin() + 2,
           {{"file_format", ParamType::String, "openexr", "openexr (or exr), rgbe (.hdr) or pfm"},
            {"pixel_format", ParamType::String, "rgb",
             "rgb, luminance or xyz, each with an alpha channel as rgba, luminance_alpha or xyza; an EXR keeps RGB "
             "and adds Y or X, Y, Z beside it"},
            {"component_format", ParamType::String, "float16", "float16 or float32 (uint32 is written as float32)"}});
  return p;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

CAUSTICA_REGISTER_PLUGIN(HdrFilm, "film", "hdrfilm", params(), {"rfilter"});

}  // namespace caustica
