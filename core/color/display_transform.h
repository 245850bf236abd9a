#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace caustica {

// The OpenColorIO config caustica ships, or $OCIO when it is set.
std::filesystem::path default_ocio_config();

// Scene-linear Rec.709 to a display through an OpenColorIO display/view
// transform.
class DisplayTransform {
 public:
  // Empty display or view: the config's defaults. Throws std::runtime_error
  // naming the config and what it lacks.
  DisplayTransform(const std::filesystem::path& config, const std::string& display, const std::string& view);

  // In place, on pixel-interleaved RGB.
  void apply(std::vector<float>& rgb, int width, int height) const;
  const std::string& display() const { return display_; }
  const std::string& view() const { return view_; }

 private:
  std::string display_, view_;
  std::shared_ptr<const void> processor_;  // OCIO::ConstCPUProcessorRcPtr, kept out of this header
};

}  // namespace caustica
