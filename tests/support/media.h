#pragma once

#include <memory>
#include <string>

#include "core/media/medium.h"

namespace caustica::test {

// The medium `element` (a <medium> written as in a scene file, without a
// name), made by the scene loader as the interior of a shape.
std::shared_ptr<const Medium> make_medium(const std::string& element);

}  // namespace caustica::test
