// The one atomic file writer (src/core/atomic_file.h): whole files or nothing, unique temporary
// files, nothing left behind on failure.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "core/atomic_file.h"
#include "temp_files.h"

namespace psx {
namespace {

namespace fs = std::filesystem;

std::vector<u8> read_all(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), {}};
}

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    // Under the temporary directory, which every user can enter (the child below may be "nobody").
    dir_ = fs::path(::testing::TempDir()) / ("psxrl_atomic_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    fs::permissions(dir_, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// Two threads write different contents to one path, many times: every rename installs a whole
// file of one writer, and no temporary file is left (each writer had its own).
TEST_F(AtomicFile, TwoWritersToOnePathDoNotCollide) {
  const fs::path p = dir_ / "shared.bin";
  const std::vector<u8> a(100000, 0xAA), b(70000, 0xBB);
  bool failed[2] = {false, false};
  auto writer = [&p](const std::vector<u8>& data, bool& failed) {
    for (int i = 0; i < 40; ++i) {
      try {
        write_file_atomically(p.string(), data);
      } catch (const std::exception&) {
        failed = true;
      }
    }
  };
  std::thread t1(writer, std::cref(a), std::ref(failed[0])), t2(writer, std::cref(b), std::ref(failed[1]));
  t1.join();
  t2.join();
  EXPECT_FALSE(failed[0]);
  EXPECT_FALSE(failed[1]);
  const std::vector<u8> got = read_all(p);
  EXPECT_TRUE(got == a || got == b) << got.size() << " bytes";
  EXPECT_FALSE(test::temporary_files_left(p));
}

// A file in a directory the writer may not write: refused naming the file, the old file intact,
// no temporary file. Root writes anywhere, so the attempt runs in a child that has become an
// ordinary user (uid and gid 65534, "nobody") when the tests run as root.
TEST_F(AtomicFile, UnwritableDirectoryLeavesTheOldFile) {
  const fs::path locked = dir_ / "locked";
  fs::create_directory(locked);
  const fs::path p = locked / "out.bin";
  write_file_atomically(p.string(), std::vector<u8>{1, 2, 3});
  // r-x for everyone: the child may list it (to look for temporary files) but not write.
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  EXPECT_EXIT(
      {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) std::_Exit(2);
        try {
          write_file_atomically(p.string(), std::vector<u8>(10, 9));
          std::_Exit(3);
        } catch (const std::runtime_error& e) {
          std::fprintf(stderr, "%s\n", e.what());
        }
        std::_Exit(read_all(p) == std::vector<u8>{1, 2, 3} && !test::temporary_files_left(p) ? 0 : 4);
      },
      ::testing::ExitedWithCode(0),
      "out\\.bin: cannot create the temporary file .*out\\.bin\\.tmp\\..*Permission denied");
  fs::permissions(locked, fs::perms::owner_all);
}

// A write that fails after the temporary file was made (the file size limit, in a child) removes
// the temporary file and leaves the old file as it was.
TEST_F(AtomicFile, WriteFailingPartWayRemovesTheTemporaryFile) {
  const fs::path p = dir_ / "big.bin";
  write_file_atomically(p.string(), std::vector<u8>(10, 7));
  EXPECT_EXIT(
      {
        rlimit limit;
        if (!test::limit_file_size(4096, limit)) std::_Exit(2);
        try {
          write_file_atomically(p.string(), std::vector<u8>(100000, 1));
          std::_Exit(3);
        } catch (const std::runtime_error& e) {
          std::fprintf(stderr, "%s\n", e.what());
        }
        std::_Exit(read_all(p) == std::vector<u8>(10, 7) && !test::temporary_files_left(p) ? 0 : 4);
      },
      ::testing::ExitedWithCode(0), "big\\.bin: write failed: File too large");
}

TEST_F(AtomicFile, MissingDirectoryIsRefusedNamingTheFile) {
  const fs::path p = dir_ / "missing" / "x.bin";
  try {
    write_file_atomically(p.string(), std::vector<u8>{1});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("x.bin: cannot create the temporary file"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
  }
}

// #61: a process killed while writing leaves "<target>.tmp.PID.N" behind; the next writer into
// the folder removes those of processes that no longer run. PID 4194305 is past Linux's largest
// possible PID (PID_MAX_LIMIT, 4194304), so no such process can exist; this process's own and a
// live process's (its parent's) temporaries are left alone, as another writer may be using them.
TEST_F(AtomicFile, StaleTemporariesOfDeadProcessesAreRemoved) {
  const std::string dead = ".tmp.4194305.", own = ".tmp." + std::to_string(::getpid()) + ".",
                    live = ".tmp." + std::to_string(::getppid()) + ".";
  for (const std::string& name : std::vector<std::string>{"curve.png" + dead + "0", "other.bin" + dead + "7", "curve.png" + own + "3",
                                  "curve.png" + live + "1", "notes.tmp.txt", "x.tmp.12ab.0"})
    std::ofstream(dir_ / name) << "left behind";
  write_file_atomically((dir_ / "curve.png").string(), std::vector<u8>{1, 2, 3});
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir_)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  std::vector<std::string> expected = {"curve.png", "curve.png" + live + "1", "curve.png" + own + "3", "notes.tmp.txt",
                                       "x.tmp.12ab.0"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(left, expected);
}

}  // namespace
}  // namespace psx
