#pragma once

#include <string>
#include <vector>

#include "core/loader/xml_node.h"

namespace caustica {

// The part of upgrading a Mitsuba 0.x object that depends on its plugin
// (its parameters already renamed to snake case): parameters renamed to
// their Mitsuba 3 or caustica names (diffuse's diffuse_reflectance, sppm's
// photon_count and initial_radius, a bitmap's uscale/vscale/uoffset/voffset
// as a to_uv transform, a sensor's shutter_open_time as its shutter_close),
// and parameters that change nothing in caustica
// removed, each with a line in `notes` saying so.
void upgrade_object_from_0x(XmlNode& object, std::vector<std::string>& notes);

}  // namespace caustica
