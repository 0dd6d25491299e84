// Outputs written whole or not at all (core/support/whole_file.h): a process killed in the middle
// of a write leaves the old file, or none, never a part of the new one; a failed write keeps the
// old file and leaves no temporary behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>

#include "whole_file.h"

namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int partial_files(const fs::path& dir) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    n += entry.path().extension() == ".partial";
  return n;
}

class WholeFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("sss-whole-file-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(WholeFile, ReplacesTheFileOrKeepsTheOldOneWhenTheWriteFails) {
  const fs::path path = dir_ / "out.txt";
  sss::write_whole_file(path.string(), [](std::ostream& out) { out << "old"; });
  EXPECT_EQ(contents(path), "old");
  EXPECT_THROW(sss::write_whole_file(path.string(),
                                     [](std::ostream& out) {
                                       out << "half of the new";
                                       throw std::runtime_error("no more data");
                                     }),
               std::runtime_error);
  EXPECT_EQ(contents(path), "old");
  EXPECT_THROW(sss::write_whole_file_named(path.string(), [](const std::string&) { return false; }),
               std::runtime_error);
  EXPECT_EQ(contents(path), "old");
  EXPECT_EQ(partial_files(dir_), 0) << "a failed write leaves its temporary file behind";
  sss::write_whole_file_named(path.string(), [](const std::string& temporary) {
    std::ofstream(temporary) << "new";
    return true;
  });
  EXPECT_EQ(contents(path), "new");
  try {
    sss::write_whole_file((dir_ / "absent" / "out.txt").string(), [](std::ostream&) {});
    ADD_FAILURE() << "wrote into a folder that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("absent/out.txt"), std::string::npos) << e.what();
  }
}

// A child process writes 32 MiB in 64 KiB pieces and is killed with SIGKILL once it has
// written the first piece; the file it was replacing must be as it was, or absent.
void kill_in_the_middle_of_a_write(const fs::path& path) {
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(ready[0]);
    sss::write_whole_file(path.string(), [&](std::ostream& out) {
      const std::string piece(64 << 10, 'n');
      for (int i = 0; i < 512; ++i) {
        out << piece << std::flush;
        if (i == 0 && write(ready[1], "w", 1) != 1) _exit(3);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
    });
    _exit(0);
  }
  close(ready[1]);
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1) << "the writer did not start";
  close(ready[0]);
  kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the writer finished before it was killed";
}

TEST_F(WholeFile, AProcessKilledMidWriteLeavesTheOldFileOrNone) {
  const fs::path replaced = dir_ / "image.pfm", fresh = dir_ / "stats.json";
  std::ofstream(replaced, std::ios::binary) << "the old image";
  kill_in_the_middle_of_a_write(replaced);
  kill_in_the_middle_of_a_write(fresh);
  EXPECT_EQ(contents(replaced), "the old image");
  EXPECT_FALSE(fs::exists(fresh));
  // The killed writers' temporary files are what they left: proof that they died mid-write.
  EXPECT_EQ(partial_files(dir_), 2);
}

}  // namespace
