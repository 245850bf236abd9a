#pragma once

#include <memory>

#include "core/media/volume.h"

namespace caustica {

// A volume with one value everywhere (what a medium's number or colour
// parameter becomes).
std::shared_ptr<const Volume> make_constant_volume(Color value);

}  // namespace caustica
