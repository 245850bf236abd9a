#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/errors/scene_error.h"
#include "core/math/color.h"
#include "core/math/sampled_spectrum.h"
#include "core/math/transform.h"
#include "core/registry/param_spec.h"
#include "core/registry/plugin.h"

namespace caustica {

enum class ValueKind { Boolean, Integer, Float, String, Rgb, Point, Vector, Transform, Object };

const char* to_string(ValueKind k);

struct ObjectValue {
  std::string category;
  std::shared_ptr<Plugin> object;
};

// One named value given to a plugin, with where it was written.
struct PropertyValue {
  using Value = std::variant<bool, int64_t, double, std::string, Color, Vec3d, Transform, ObjectValue>;
  PropertyValue() = default;
  PropertyValue(ValueKind k, Value v, SourceLocation w, std::shared_ptr<const SampledSpectrum> s = nullptr)
      : kind(k), value(std::move(v)), where(std::move(w)), spectrum(std::move(s)) {}

  ValueKind kind = ValueKind::Float;
  Value value;
  SourceLocation where;
  // For a colour given as a spectrum (sampled, from a file, a black body):
  // the spectrum itself, which spectral transport reads in place of the
  // colour RGB transport takes for it.
  std::shared_ptr<const SampledSpectrum> spectrum;
};

// The numbers of a list such as "1, 2, 3" or "1 0 0 0 ..." (commas and/or
// whitespace between them, an explicit '+' allowed); throws SceneError at
// `where`, calling the whole text a `what`, on anything else.
std::vector<double> parse_numbers(const std::string& text, const SourceLocation& where, const char* what);

// Parses the text of a value element of kind `kind` (as in <float value="...">);
// throws SceneError at `where` on malformed text.
PropertyValue parse_value_text(ValueKind kind, const std::string& text, const SourceLocation& where);

// Whether a value of kind `given` may be passed where `wanted` is declared
// (an integer is a valid float, a float a valid grey colour, and so on).
bool kind_fits(ValueKind given, ParamType wanted, const std::string& object_category);

// The value kind a parameter's default text is parsed as.
ValueKind default_kind(ParamType t);

// A colour value; numbers stand for grey.
Color as_color(const PropertyValue& v);

}  // namespace caustica
