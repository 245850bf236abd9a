#include "core/loader/spectrum_value.h"

#include <limits>
#include <stdexcept>
#include <vector>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// A number as value attributes hold them; a temperature may end in K.
double number(const XmlNode& node, const std::string& text, const char* what) {
  std::string t = text;
  if (!t.empty() && (t.back() == 'K' || t.back() == 'k')) t.pop_back();
  const std::vector<double> n = parse_numbers(t, node.where, what);
  if (n.size() != 1) throw SceneError(node.where, "cannot parse '" + text + "' as " + what);
  return n[0];
}

// The colour RGB transport takes for a spectrum, with the spectrum. A
// saturated spectrum (a narrow band) lies outside the Rec.709 gamut; RGB
// transport takes its colour's non-negative part.
PropertyValue spectral(const XmlNode& node, SampledSpectrum s) {
  const Color c = spectrum_to_rgb(s).clamp(0, std::numeric_limits<float>::infinity());
  return {ValueKind::Rgb, c, node.where, std::make_shared<const SampledSpectrum>(std::move(s))};
}

PropertyValue from_blackbody(const XmlNode& node, double kelvin, double scale) {
  if (!(kelvin > 0)) throw SceneError(node.where, "a black body's temperature must be positive");
  if (!(scale >= 0)) throw SceneError(node.where, "a black body's scale must not be negative");
  SampledSpectrum s = blackbody(kelvin);
  for (double& v : s.values) v *= scale;
  return spectral(node, std::move(s));
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

PropertyValue parse_spectrum_element(const XmlNode& node, const FileResolver& files) {
  if (node.tag == "blackbody") {
    node.check_attributes({"name", "temperature", "multiplier", "scale"});
    const std::string* t = node.attribute("temperature");
    if (!t) throw SceneError(node.where, "<blackbody> needs a 'temperature' attribute");
    const std::string* m = node.attribute("multiplier") ? node.attribute("multiplier") : node.attribute("scale");
    return from_blackbody(node, number(node, *t, "a temperature"), m ? number(node, *m, "a multiplier") : 1);
  }
  if (const std::string* type = node.attribute("type")) {
    node.check_attributes({"name", "type"});
    if (*type != "blackbody")
      throw SceneError(node.where, "<spectrum type='" + type->substr(0, 40) + "'> is not known (known: blackbody)");
    double kelvin = 0, scale = 1;
    for (const XmlNode& child : node.children) {
      const std::string* name = child.attribute("name");
      const std::string* value = child.attribute("value");
      if (child.tag != "float" || !name || !value || (*name != "temperature" && *name != "scale"))
        throw SceneError(child.where, "a black body takes <float name='temperature'> and <float name='scale'>");
      (*name == "temperature" ? kelvin : scale) = number(child, *value, name->c_str());
    }
    return from_blackbody(node, kelvin, scale);
  }
  node.check_attributes({"name", "value", "filename"});
  try {
    if (const std::string* file = node.attribute("filename")) {
      return spectral(node, read_spd_file(files.resolve(*file, node.where.file)));
    }
    const std::string* text = node.attribute("value");
    if (!text) throw SceneError(node.where, "<spectrum> needs a 'value' or a 'filename' attribute");
    if (text->find(':') == std::string::npos) return parse_value_text(ValueKind::Rgb, *text, node.where);
    return spectral(node, parse_spectrum_pairs(*text));
  } catch (const std::invalid_argument& e) {
    throw SceneError(node.where, std::string("<spectrum>: ") + e.what());
  }
}

}  // namespace caustica
