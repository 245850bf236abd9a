#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace caustica {

// The OpenColorIO config caustica ships, or $OCIO when it is set.
std::filesystem::path default_ocio_config();

// Scene-linear Rec.709 to a display through an OpenColorIO display/view
// transform.
class DisplayTransform {
 public:
  // Empty display or view: the config's defaults; an empty look: the view's
  // own. Throws std::runtime_error naming the config and what it lacks.
  DisplayTransform(const std::filesystem::path& config, const std::string& display, const std::string& view,
                   const std::string& look = "");

  // In place, on pixel-interleaved RGB.
  void apply(std::vector<float>& rgb, int width, int height) const;
  const std::string& display() const { return display_; }
  const std::string& view() const { return view_; }
  const std::string& look() const { return look_; }

 private:
  std::string display_, view_, look_;
  std::shared_ptr<const void> processor_;  // OCIO::ConstCPUProcessorRcPtr, kept out of this header
};

}  // namespace caustica
