#include "core/media/vdb_header_check.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <utility>
#include <vector>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

// Reads little-endian fields in order, knowing how many bytes are left.
class HeaderReader {
 public:
  explicit HeaderReader(const std::filesystem::path& file) : in_(file, std::ios::binary) {
    in_.seekg(0, std::ios::end);
    size_ = in_ ? uint64_t(in_.tellg()) : 0;
    in_.seekg(0);
  }

  uint64_t size() const { return size_; }
  uint64_t at() const { return at_; }
  uint64_t left() const { return size_ - at_; }
  bool seek(uint64_t to) {
    if (to > size_) return false;
    in_.clear();
    in_.seekg(std::streamoff(to));
    at_ = to;
    return bool(in_);
  }
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

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
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
  std::vector<std::pair<int64_t, int64_t>> grids;  // where each grid's own part and its topology begin
  for (int32_t i = 0; i < count; ++i) {
    int64_t grid = 0, block = 0, end = 0;
    if (!in.sized() || !in.sized() || !in.sized() || !in.value(&grid) || !in.value(&block) || !in.value(&end))
      return cut + "grid " + std::to_string(i + 1) + "'s description claims more bytes than the file holds";
    if (grid < 0 || block < grid || end < block || uint64_t(end) > in.size())
      return cut + "grid " + std::to_string(i + 1) + " ends at byte " + std::to_string(end) + " of a file of " +
             std::to_string(in.size()) + " bytes";
    grids.emplace_back(grid, block);
  }
  // Each grid opens with its compression flags, its own metadata and the
  // name of its transform's type, all of which must end before its
  // topology begins: a wrong length there is what OpenVDB would allocate.
  for (size_t i = 0; i < grids.size(); ++i) {
    const int64_t grid = grids[i].first, block = grids[i].second;
    const std::string which = "grid " + std::to_string(i + 1) + "'s ";
    uint32_t compression = 0;
    int32_t entries = 0;
    if (!in.seek(uint64_t(grid)) || !in.value(&compression) || !in.value(&entries) || entries < 0 ||
        in.at() > uint64_t(block))
      return cut + which + "metadata count is missing or negative";
    const auto field = [&](const std::string& what) -> std::string {
      if (!in.sized()) return cut + which + what + " claims more bytes than the file holds";
      if (in.at() > uint64_t(block))
        return cut + which + what + " runs to byte " + std::to_string(in.at()) + ", past the grid's data at byte " +
               std::to_string(block);
      return "";
    };
    for (int32_t e = 0; e < entries; ++e)
      for (int part = 0; part < 3; ++part)
        if (std::string problem = field("metadata entry " + std::to_string(e + 1)); !problem.empty()) return problem;
    if (std::string problem = field("transform type"); !problem.empty()) return problem;
  }
  return "";
}

}  // namespace caustica
