#include "core/files/input_file.h"

namespace caustica {

std::string input_file_problem(const std::filesystem::path& file) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) return "not found";
  if (std::filesystem::is_directory(status)) return "is a directory";
  if (!std::filesystem::is_regular_file(status)) return "is not a regular file (a device or a pipe)";
  return "";
}

}  // namespace caustica
