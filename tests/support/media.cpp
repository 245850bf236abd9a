#include "tests/support/media.h"

#include "core/registry/properties.h"
#include "tests/support/test_scenes.h"

namespace caustica::test {

std::shared_ptr<const Medium> make_medium(const std::string& element) {
  const std::string named = "<medium name='interior' " + element.substr(element.find("<medium") + 7);
  const auto scene =
      scene_from_xml("<scene version='3.0.0'><shape type='rectangle'>" + named + "</shape></scene>", "medium.xml");
  const Shape& shape = *scene->shapes().front();
  // The shape holds the medium; the copy shares its ownership with the scene.
  return std::shared_ptr<const Medium>(scene.scene, shape.interior());
}

std::shared_ptr<const Volume> make_grid_volume(const std::filesystem::path& file, const std::string& filter,
                                               const std::string& grid) {
  const PluginInfo& info = *Registry::instance().find("volume", "gridvolume");
  const SourceLocation where{"grid.xml", 1};
  Properties props(info, where);
  props.set("filename", {ValueKind::String, file.string(), where});
  props.set("filter_type", {ValueKind::String, filter, where});
  props.set("grid", {ValueKind::String, grid, where});
  return std::dynamic_pointer_cast<const Volume>(info.create(props));
}

}  // namespace caustica::test
