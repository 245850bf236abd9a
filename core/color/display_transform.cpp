#include "core/color/display_transform.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cstdlib>
#include <stdexcept>

#include "core/install/data_files.h"

namespace OCIO = OCIO_NAMESPACE;

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// OpenColorIO's own messages for an unknown display, view or look do not
// say what the config offers; these name `wanted` and list what it has.
template <class Name>
void require_named(const std::string& wanted, int count, Name&& name, const std::string& problem) {
  std::string list;
  for (int i = 0; i < count; ++i) {
    if (wanted == name(i)) return;
    list += (i ? ", " : "") + std::string(name(i));
  }
  throw std::runtime_error(problem + " (it has " + (list.empty() ? "none" : list) + ")");
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

std::filesystem::path default_ocio_config() {
  if (const char* env = std::getenv("OCIO"); env && *env) return env;
  return data_file("config.ocio", CAUSTICA_OCIO_CONFIG);
}

DisplayTransform::DisplayTransform(const std::filesystem::path& config_path, const std::string& display,
                                   const std::string& view, const std::string& look)
    : look_(look) {
  try {
    const OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(config_path.c_str());
    display_ = display.empty() ? config->getDefaultDisplay() : display;
    require_named(
        display_, config->getNumDisplays(), [&](int i) { return config->getDisplay(i); },
        "no display named '" + display_ + "'");
    view_ = view.empty() ? config->getDefaultView(display_.c_str()) : view;
    require_named(
        view_, config->getNumViews(display_.c_str()), [&](int i) { return config->getView(display_.c_str(), i); },
        "display '" + display_ + "' has no view named '" + view_ + "'");
    auto transform = OCIO::DisplayViewTransform::Create();
    transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
    transform->setDisplay(display_.c_str());
    transform->setView(view_.c_str());
    auto pipeline = OCIO::LegacyViewingPipeline::Create();
    pipeline->setDisplayViewTransform(transform);
    if (!look.empty()) {
      require_named(
          look, config->getNumLooks(), [&](int i) { return config->getLookNameByIndex(i); },
          "no look named '" + look + "'");
      pipeline->setLooksOverrideEnabled(true);
      pipeline->setLooksOverride(look.c_str());
    }
    auto cpu = pipeline->getProcessor(config)->getDefaultCPUProcessor();
    processor_ = std::shared_ptr<const void>(cpu, cpu.get());
  } catch (const std::exception& e) {
    throw std::runtime_error("OpenColorIO config '" + config_path.string() + "': " + e.what());
  }
}

void DisplayTransform::apply(std::vector<float>& rgb, int width, int height) const {
  const auto* cpu = static_cast<const OCIO::CPUProcessor*>(processor_.get());
  OCIO::PackedImageDesc desc(rgb.data(), width, height, 3);
  cpu->apply(desc);
}

}  // namespace caustica
