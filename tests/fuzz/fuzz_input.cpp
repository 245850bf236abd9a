#include "tests/fuzz/fuzz_input.h"

#include <unistd.h>

#include <fstream>

namespace caustica::fuzz {

std::filesystem::path input_file(const uint8_t* data, size_t size, const std::string& extension) {
  const std::filesystem::path shm = "/dev/shm";
  const std::filesystem::path dir =
      (std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path()) /
      ("caustica-fuzz-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / ("input" + extension);
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return file;
}

std::string scene_with(const std::string& element) { return "<scene version='3.0.0'>" + element + "</scene>"; }

}  // namespace caustica::fuzz
