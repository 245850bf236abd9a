#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/errors/scene_error.h"

namespace caustica {

// One element of a scene file, detached from the XML library, carrying the
// place it came from so every later stage can report errors there.
struct XmlNode {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> attributes;  // in file order
  std::vector<XmlNode> children;
  SourceLocation where;

  const std::string* attribute(std::string_view name) const {
    for (const auto& [key, value] : attributes)
      if (key == name) return &value;
    return nullptr;
  }

  // Throws if the element carries an attribute outside `allowed`: a typo
  // such as valeu="..." must not pass silently.
  void check_attributes(std::initializer_list<std::string_view> allowed) const {
    for (const auto& [key, value] : attributes) {
      bool ok = false;
      for (std::string_view a : allowed) ok = ok || key == a;
      if (!ok) throw SceneError(where, "unexpected attribute '" + key + "' on <" + tag + ">");
    }
  }
};

}  // namespace caustica
