#include "core/image/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace caustica {
namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path fresh_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "caustica_atomic_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(AtomicFile, FailureMidWriteKeepsThePreviousFile) {
  const auto dir = fresh_dir();
  const auto target = dir / "render.exr";
  std::ofstream(target) << "previous image";
  EXPECT_THROW(write_atomically(target,
                                [](const std::filesystem::path& tmp) {
                                  std::ofstream(tmp) << "half of a new ima";
                                  throw std::runtime_error("disk full");
                                }),
               std::runtime_error);
  EXPECT_EQ(read(target), "previous image");
  // The partial temporary file is gone too.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
}

// What a signal handler calls before the process ends mid-write.
TEST(AtomicFile, ThePendingTemporaryFileCanBeRemovedFromASignalHandler) {
  const auto dir = fresh_dir();
  const auto target = dir / "render.exr";
  std::ofstream(target) << "previous image";
  std::filesystem::path seen;
  EXPECT_THROW(write_atomically(target,
                                [&](const std::filesystem::path& tmp) {
                                  seen = tmp;
                                  std::ofstream(tmp) << "half of a new ima";
                                  remove_pending_temporary_file();
                                  EXPECT_FALSE(std::filesystem::exists(tmp));
                                  throw std::runtime_error("killed");
                                }),
               std::runtime_error);
  EXPECT_FALSE(seen.empty());
  EXPECT_EQ(read(target), "previous image");
  // Nothing is pending once a write has ended.
  write_atomically(target, [&](const std::filesystem::path& tmp) { std::ofstream(tmp) << "new"; });
  std::ofstream(seen) << "someone else's file";
  remove_pending_temporary_file();
  EXPECT_TRUE(std::filesystem::exists(seen));
}

TEST(AtomicFile, SuccessReplacesInOneStep) {
  const auto dir = fresh_dir();
  const auto target = dir / "render.png";
  std::ofstream(target) << "old";
  std::filesystem::path seen;
  write_atomically(target, [&](const std::filesystem::path& tmp) {
    seen = tmp;
    EXPECT_EQ(tmp.extension(), ".png");  // so image libraries still recognise the format
    EXPECT_EQ(tmp.parent_path(), dir);   // same file system: the rename is atomic
    EXPECT_EQ(read(target), "old");      // untouched until the rename
    std::ofstream(tmp) << "new";
  });
  EXPECT_EQ(read(target), "new");
  EXPECT_FALSE(std::filesystem::exists(seen));
}

}  // namespace
}  // namespace caustica
