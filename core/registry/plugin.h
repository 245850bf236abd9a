#pragma once

namespace caustica {

// Base of every object a scene file can name with type="...".
class Plugin {
 public:
  virtual ~Plugin() = default;
};

}  // namespace caustica
