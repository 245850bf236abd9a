#include "core/media/vdb_header_check.h"

#include <cstdint>
#include <cstring>
#include <fstream>

namespace caustica {
namespace {

// Reads little-endian fields in order, knowing how many bytes are left.
class HeaderReader {
 public:
  explicit HeaderReader(const std::filesystem::path& file) : in_(file, std::ios::binary) {
    in_.seekg(0, std::ios::end);
    size_ = in_ ? uint64_t(in_.tellg()) : 0;
    in_.seekg(0);
  }

  uint64_t size() const { return size_; }
  uint64_t left() const { return size_ - at_; }
  bool read(void* out, uint64_t bytes) {
    if (bytes > left() || !in_.read(static_cast<char*>(out), std::streamsize(bytes))) return false;
    at_ += bytes;
    return true;
  }
  bool skip(uint64_t bytes) {
    if (bytes > left()) return false;
    in_.seekg(std::streamoff(bytes), std::ios::cur);
    at_ += bytes;
    return bool(in_);
  }
  template <class T>
  bool value(T* out) {
    return read(out, sizeof(T));
  }
  // A string or value prefixed by its uint32 length, skipped.
  bool sized() {
    uint32_t length = 0;
    return value(&length) && skip(length);
  }

 private:
  std::ifstream in_;
  uint64_t size_ = 0, at_ = 0;
};

}  // namespace

std::string vdb_header_problem(const std::filesystem::path& file) {
  HeaderReader in(file);
  const std::string cut = "is cut short or corrupt: ";
  int64_t magic = 0;
  uint32_t version = 0, major = 0, minor = 0;
  // What is not an OpenVDB file of a known version is OpenVDB's to refuse.
  if (!in.value(&magic) || magic != 0x56444220 || !in.value(&version) || version < 222 || version > 224) return "";
  char has_offsets = 0, uuid[36];
  if (!in.value(&major) || !in.value(&minor) || !in.value(&has_offsets) || !in.read(uuid, sizeof uuid))
    return cut + "its header ends after " + std::to_string(in.size()) + " bytes";
  int32_t count = 0;
  if (!in.value(&count) || count < 0) return cut + "its metadata count is missing or negative";
  for (int32_t i = 0; i < count; ++i)
    if (!in.sized() || !in.sized() || !in.sized())
      return cut + "metadata entry " + std::to_string(i + 1) + " claims more bytes than the file holds";
  if (!has_offsets) return "";
  if (!in.value(&count) || count < 0) return cut + "its grid count is missing or negative";
  for (int32_t i = 0; i < count; ++i) {
    int64_t grid = 0, block = 0, end = 0;
    if (!in.sized() || !in.sized() || !in.sized() || !in.value(&grid) || !in.value(&block) || !in.value(&end))
      return cut + "grid " + std::to_string(i + 1) + "'s description claims more bytes than the file holds";
    if (grid < 0 || block < grid || end < block || uint64_t(end) > in.size())
      return cut + "grid " + std::to_string(i + 1) + " ends at byte " + std::to_string(end) + " of a file of " +
             std::to_string(in.size()) + " bytes";
  }
  return "";
}

}  // namespace caustica
