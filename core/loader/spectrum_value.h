#pragma once

#include "core/color/spectrum_to_rgb.h"
#include "core/loader/xml_node.h"
#include "core/registry/file_resolver.h"
#include "core/registry/property_value.h"

namespace caustica {

// A <spectrum> (or Mitsuba 0.x <blackbody>) element as the RGB value it
// stands for: a single value is a grey; wavelength:value pairs, a .spd
// file (filename, found by `files`) or a black body
// (<spectrum type="blackbody"> with a nested temperature, or 0.x's
// <blackbody temperature="5000K" multiplier="..."/>) are integrated against
// the CIE 1931 colour matching functions (spectrum_to_rgb). Throws
// SceneError at the element.
PropertyValue parse_spectrum_element(const XmlNode& node, const FileResolver& files);

}  // namespace caustica
