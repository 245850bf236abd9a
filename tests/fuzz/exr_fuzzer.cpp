// EXR files as `merge` and `compare` read them: read, merged with a copy of
// themselves under another seed, and compared with themselves.

#include <cstdint>
#include <exception>

#include "core/image/image_metrics.h"
#include "core/image/render_merge.h"
#include "core/job/range_merge.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = caustica::fuzz::input_file(data, size, ".exr");
  try {
    const caustica::RenderFile render = caustica::read_render(file.string());
    caustica::compare_images(render.image, render.image);
    caustica::estimated_error(render.image);
    try {
      caustica::merge_sample_ranges({render, render});
    } catch (const std::exception&) {
    }
    caustica::RenderFile other = render;
    other.path = "other.exr";
    other.metadata["caustica:seed"] += "1";
    other.metadata.erase("caustica:seeds");
    caustica::merge_renders({render, other});
  } catch (const std::exception&) {
  }
  return 0;
}
