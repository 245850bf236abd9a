#include "core/loader/upgrade_0x.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "core/color/srgb_transfer.h"
#include "core/math/color.h"
#include "core/registry/property_value.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

struct Rename {
  const char* tag;
  const char* type;  // "" for any
  const char* from;
  const char* to;
};

const Rename kRenames[] = {{"bsdf", "diffuse", "diffuse_reflectance", "reflectance"},
                           {"integrator", "sppm", "photon_count", "photons"},
                           {"integrator", "sppm", "initial_radius", "radius"}};

struct Ignored {
  const char* tag;
  const char* name;
  const char* why;
};

const Ignored kIgnored[] = {
    {"integrator", "strict_normals", "caustica's paths always treat shading normals consistently"},
    {"integrator", "max_passes", "sppm runs one iteration per sample per pixel"},
    {"integrator", "granularity", "work is scheduled by tiles"},
    {"integrator", "direct_samples", "direct light is sampled once per vertex"},
    {"integrator", "glossy_samples", "glossy lobes are sampled once per vertex"},
    {"integrator", "light_image", "bdpt always joins light paths to the camera"},
    {"integrator", "sample_direct", "bdpt always samples every strategy"},
    {"emitter", "sampling_weight", "emitters are chosen in proportion to their power"},
    {"sampler", "dimension", "caustica's samplers draw as many dimensions as each path needs"},
    {"bsdf", "preserve_colors", "the material's colours are used as given"},
    {"texture", "max_anisotropy", "caustica keeps no MIP maps to filter anisotropically"},
    {"texture", "cache", "caustica reads the image itself and keeps no MIP-map cache file"}};

bool has_name(const XmlNode& child, const char* name) {
  const std::string* n = child.attribute("name");
  return n && *n == name;
}

// 0.x bitmaps take uv = uv * (uscale, vscale) + (uoffset, voffset);
// caustica's take a to_uv transform.
void upgrade_uv_transform(XmlNode& bitmap) {
  std::string scale[2] = {"1", "1"}, offset[2] = {"0", "0"};
  bool any = false;
  std::erase_if(bitmap.children, [&](const XmlNode& child) {
    const char* names[] = {"uscale", "vscale", "uoffset", "voffset"};
    for (int i = 0; i < 4; ++i)
      if (has_name(child, names[i]) && child.attribute("value")) {
        (i < 2 ? scale : offset)[i % 2] = *child.attribute("value");
        return any = true;
      }
    return false;
  });
  if (!any) return;
  XmlNode transform{"transform", {{"name", "to_uv"}}, {}, bitmap.where};
  transform.children.push_back({"scale", {{"x", scale[0]}, {"y", scale[1]}}, {}, bitmap.where});
  transform.children.push_back({"translate", {{"x", offset[0]}, {"y", offset[1]}}, {}, bitmap.where});
  bitmap.children.push_back(std::move(transform));
}

// 0.x bitmaps override the file's transfer function by `gamma`: 1 reads
// the values as stored (caustica's raw), -1 (the default) as the file says.
// Their MIP-mapped filters (ewa, the default, and trilinear) are read as
// bilinear: caustica keeps no MIP maps.
void upgrade_bitmap(XmlNode& bitmap, std::vector<std::string>& notes) {
  for (XmlNode& child : bitmap.children) {
    const std::string* value = child.attribute("value");
    if (!value) continue;
    if (has_name(child, "gamma") && (*value == "1" || *value == "1.0")) {
      child = XmlNode{"boolean", {{"name", "raw"}, {"value", "true"}}, {}, child.where};
    } else if (has_name(child, "filter_type") && (*value == "ewa" || *value == "trilinear")) {
      notes.push_back(child.where.str() + ": filter_type '" + *value +
                      "' (Mitsuba 0.x) is read as bilinear: caustica keeps no MIP maps");
      child = XmlNode{"string", {{"name", "filter_type"}, {"value", "bilinear"}}, {}, child.where};
    }
  }
  std::erase_if(bitmap.children, [](const XmlNode& child) {
    const std::string* value = child.attribute("value");
    return has_name(child, "gamma") && value && (*value == "-1" || *value == "-1.0");
  });
}

// 0.x sensors give the shutter's opening and how long it stays open
// (shutter_open_time); caustica's give its opening and closing.
void upgrade_shutter(XmlNode& sensor) {
  const auto number = [](const XmlNode& child) -> std::optional<double> {
    const std::string* v = child.attribute("value");
    if (!v) return std::nullopt;
    char* end = nullptr;
    const double x = std::strtod(v->c_str(), &end);
    if (end == v->c_str() || *end != '\0' || !std::isfinite(x)) return std::nullopt;
    return x;
  };
  double open = 0;
  XmlNode* duration = nullptr;
  for (XmlNode& child : sensor.children) {
    if (has_name(child, "shutter_open") && number(child)) open = *number(child);
    if (has_name(child, "shutter_open_time")) duration = &child;
  }
  if (!duration || !number(*duration)) return;
  char close[32];
  std::snprintf(close, sizeof close, "%.17g", open + *number(*duration));
  *duration = XmlNode{"float", {{"name", "shutter_close"}, {"value", close}}, {}, duration->where};
}

// "#rrggbb" as a colour in [0, 1]^3, or none.
std::optional<Color> parse_hex_colour(const std::string& text) {
  if (text.size() != 7 || text[0] != '#') return std::nullopt;
  float out[3];
  for (int i = 0; i < 3; ++i) {
    unsigned byte = 0;
    const char* begin = text.data() + 1 + 2 * i;
    const auto [end, ec] = std::from_chars(begin, begin + 2, byte, 16);
    if (ec != std::errc() || end != begin + 2) return std::nullopt;
    out[i] = float(byte) / 255;
  }
  return Color(out[0], out[1], out[2]);
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void upgrade_srgb(XmlNode& srgb) {
  srgb.tag = "rgb";
  for (auto& [key, value] : srgb.attributes) {
    if (key != "value") continue;
    std::optional<Color> encoded = parse_hex_colour(value);
    if (!encoded) {
      try {
        encoded = std::get<Color>(parse_value_text(ValueKind::Rgb, value, srgb.where).value);
      } catch (const SceneError&) {
        return;  // left for the parser to refuse, with its message
      }
    }
    char text[96];
    std::snprintf(text, sizeof text, "%.9g, %.9g, %.9g", double(srgb_to_linear(encoded->r)),
                  double(srgb_to_linear(encoded->g)), double(srgb_to_linear(encoded->b)));
    value = text;
  }
}

void upgrade_object_from_0x(XmlNode& object, std::vector<std::string>& notes) {
  const std::string* type_attribute = object.attribute("type");
  const std::string type = type_attribute ? *type_attribute : "";
  for (XmlNode& child : object.children) {
    std::string* name = nullptr;
    for (auto& [key, value] : child.attributes)
      if (key == "name") name = &value;
    if (!name) continue;
    for (const Rename& r : kRenames)
      if (object.tag == r.tag && (!*r.type || type == r.type) && *name == r.from) *name = r.to;
  }
  if (object.tag == "texture" && (type == "bitmap" || type == "checkerboard")) upgrade_uv_transform(object);
  if (object.tag == "texture" && type == "bitmap") upgrade_bitmap(object, notes);
  if (object.tag == "integrator" && type == "volpath_simple") {
    notes.push_back(object.where.str() +
                    ": integrator 'volpath_simple' (Mitsuba 0.x) is rendered by volpath, "
                    "which samples the same paths and also weighs them by MIS");
    for (auto& [key, value] : object.attributes)
      if (key == "type") value = "volpath";
  }
  if (object.tag == "sensor") upgrade_shutter(object);
  std::erase_if(object.children, [&](const XmlNode& child) {
    for (const Ignored& i : kIgnored)
      if (object.tag == i.tag && has_name(child, i.name)) {
        notes.push_back(child.where.str() + ": parameter '" + i.name + "' of " + object.tag + " '" + type +
                        "' (Mitsuba 0.x) is ignored: " + i.why);
        return true;
      }
    return false;
  });
}

}  // namespace caustica
