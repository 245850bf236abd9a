#pragma once

#include <string>
#include <vector>

#include "core/loader/xml_node.h"

namespace caustica {

// The part of upgrading a Mitsuba 0.x object that depends on its plugin
// (its parameters already renamed to snake case): parameters renamed to
// their Mitsuba 3 or caustica names (diffuse's diffuse_reflectance, sppm's
// photon_count and initial_radius, a bitmap's or checkerboard's
// uscale/vscale/uoffset/voffset as a to_uv transform, a bitmap's gamma 1 as
// raw and its MIP-mapped filters as bilinear, a sensor's shutter_open_time
// as its shutter_close), volpath_simple as volpath, and parameters that
// change nothing in caustica removed, each with a line in `notes` saying so.
void upgrade_object_from_0x(XmlNode& object, std::vector<std::string>& notes);

// A 0.x <srgb> value (numbers, or #rrggbb as 0.x's documentation writes
// colours) as the <rgb> of its linear values: 0.x decodes sRGB's transfer
// function. A value that is neither is left for the parser to refuse.
void upgrade_srgb(XmlNode& srgb);

}  // namespace caustica
