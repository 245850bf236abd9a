#include "core/image/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

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

// SIGKILL leaves a temporary file no handler could remove: the next write
// into the folder removes those whose writer no longer exists, and only
// those (a live writer's, this process's, and files merely named alike).
TEST(AtomicFile, AKilledWritersTemporaryFileIsRemovedByTheNextWrite) {
  const auto dir = fresh_dir();
  const pid_t child = fork();
  if (child == 0) _exit(0);
  ASSERT_GT(child, 0);
  int status = 0;
  waitpid(child, &status, 0);
  const std::string dead = std::to_string(child), alive = std::to_string(getppid()), own = std::to_string(getpid());
  const std::vector<std::string> stale = {".render.tmp" + dead + ".exr", ".other.tmp" + dead + ".png",
                                          ".noext.tmp" + dead};
  const std::vector<std::string> kept = {".render.tmp" + alive + ".exr", ".render.tmp" + own + ".exr",
                                         "render.tmp" + dead + ".exr",   ".render.tmp" + dead + ".exr.bak",
                                         ".render.tmpx" + dead + ".exr", "notes.txt"};
  for (const auto& name : stale) std::ofstream(dir / name) << "left by a killed render";
  for (const auto& name : kept) std::ofstream(dir / name) << "someone's";
  write_atomically(dir / "image.exr", [](const std::filesystem::path& tmp) { std::ofstream(tmp) << "new"; });
  for (const auto& name : stale) EXPECT_FALSE(std::filesystem::exists(dir / name)) << name;
  for (const auto& name : kept) EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  EXPECT_EQ(read(dir / "image.exr"), "new");
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

}  // namespace CAUSTICA_UNITY_ID
}  // namespace
}  // namespace caustica
