#pragma once

#include "core/loader/xml_node.h"
#include "core/math/transform.h"

namespace caustica {

// Composes a <transform>'s children (translate, rotate, scale, matrix,
// lookat) in file order, each applied after the previous ones.
Transform parse_transform(const XmlNode& node);

}  // namespace caustica
