#include "core/color/display_transform.h"

#include <OpenColorIO/OpenColorIO.h>

#include <cstdlib>
#include <stdexcept>

#include "core/install/data_files.h"

namespace OCIO = OCIO_NAMESPACE;

namespace caustica {

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
    view_ = view.empty() ? config->getDefaultView(display_.c_str()) : view;
    auto transform = OCIO::DisplayViewTransform::Create();
    transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
    transform->setDisplay(display_.c_str());
    transform->setView(view_.c_str());
    auto pipeline = OCIO::LegacyViewingPipeline::Create();
    pipeline->setDisplayViewTransform(transform);
    if (!look.empty()) {
      if (!config->getLook(look.c_str())) throw std::runtime_error("no look named '" + look + "'");
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
