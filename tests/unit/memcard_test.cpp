// Memory card command bytes (psx-spx "Memory Card Read/Write Commands"), the blank-card format
// ("Memory Card Data Format") and the image file handling (size check, unreadable files, creation
// on first write, atomic replacement).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/sio/memory_card.h"
#include "sio_test_util.h"
#include "temp_files.h"

namespace psx {
namespace {

namespace fs = std::filesystem;
using test::acks_but_last;
using test::command;
using V = std::vector<u8>;

// Bytes of a read command for `sector`: 81h 52h 00h 00h MSB LSB, then 00h for 5Ch 5Dh, the
// confirmed address, 128 data bytes, checksum and end byte.
V read_bytes(u16 sector) {
  V v = {0x81, 0x52, 0x00, 0x00, static_cast<u8>(sector >> 8), static_cast<u8>(sector)};
  v.resize(6 + 4 + 128 + 2, 0x00);
  return v;
}

// Write command: 81h 57h 00h 00h MSB LSB, 128 data bytes, checksum, then 00h 00h 00h.
V write_bytes(u16 sector, const V& data, int checksum_adjust = 0) {
  V v = {0x81, 0x57, 0x00, 0x00, static_cast<u8>(sector >> 8), static_cast<u8>(sector)};
  u8 chk = static_cast<u8>((sector >> 8) ^ (sector & 0xFF));
  for (u8 d : data) {
    v.push_back(d);
    chk ^= d;
  }
  v.push_back(static_cast<u8>(chk + checksum_adjust));
  v.insert(v.end(), {0x00, 0x00, 0x00});
  return v;
}

V pattern(u8 seed) {
  V d(128);
  for (int i = 0; i < 128; ++i) d[i] = static_cast<u8>(seed + i * 3);
  return d;
}

V read_sector_data(MemoryCard& card, u16 sector) {
  auto e = command(card, read_bytes(sector));
  return V(e.replies.begin() + 10, e.replies.begin() + 138);
}

TEST(MemcardProtocol, GetIdReplies) {
  MemoryCard card;
  auto e = command(card, {0x81, 0x53, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0x08, 0x5A, 0x5D, 0x5C, 0x5D, 0x04, 0x00, 0x00, 0x80}));
  EXPECT_EQ(e.acks, acks_but_last(10));
}

TEST(MemcardProtocol, ReadHeaderOfBlankCard) {
  MemoryCard card;
  auto e = command(card, read_bytes(0x0000));
  ASSERT_EQ(e.replies.size(), 140u);
  EXPECT_EQ((V(e.replies.begin(), e.replies.begin() + 10)),
            (V{0xFF, 0x08, 0x5A, 0x5D, 0x00, 0x00, 0x5C, 0x5D, 0x00, 0x00}));
  // Header frame: "MC", zeros, byte 7Fh = 'M' ^ 'C' = 4Dh ^ 43h = 0Eh.
  EXPECT_EQ(e.replies[10], 'M');
  EXPECT_EQ(e.replies[11], 'C');
  for (int i = 2; i < 127; ++i) EXPECT_EQ(e.replies[10 + i], 0x00) << i;
  EXPECT_EQ(e.replies[137], 0x0E);
  // Checksum = MSB ^ LSB ^ data = 0 ^ 0 ^ (4Dh ^ 43h ^ 0Eh) = 00h; end byte 47h, no /ACK.
  EXPECT_EQ(e.replies[138], 0x00);
  EXPECT_EQ(e.replies[139], 0x47);
  EXPECT_EQ(e.acks, acks_but_last(140));
}

TEST(MemcardProtocol, BlankCardDirectoryIsFree) {
  MemoryCard card;
  for (u16 frame = 1; frame <= 15; ++frame) {
    V d = read_sector_data(card, frame);
    EXPECT_EQ(d[0], 0xA0) << frame;  // free, freshly formatted
    EXPECT_EQ(d[8], 0xFF);
    EXPECT_EQ(d[9], 0xFF);
    EXPECT_EQ(d[127], 0xA0 ^ 0xFF ^ 0xFF);
  }
  V broken = read_sector_data(card, 16);
  EXPECT_EQ((V(broken.begin(), broken.begin() + 4)), (V{0xFF, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(read_sector_data(card, 63), read_sector_data(card, 0));  // write-test frame
}

TEST(MemcardProtocol, WriteRepliesAndReadBack) {
  MemoryCard card;
  const u16 sector = 0x0123;
  const V data = pattern(0x11);
  auto e = command(card, write_bytes(sector, data));
  ASSERT_EQ(e.replies.size(), 138u);
  EXPECT_EQ((V(e.replies.begin(), e.replies.begin() + 6)), (V{0xFF, 0x08, 0x5A, 0x5D, 0x00, 0x01}));
  // Each data/checksum byte is answered with the byte sent before it.
  EXPECT_EQ(e.replies[6], 0x23);
  for (int i = 1; i < 128; ++i) EXPECT_EQ(e.replies[6 + i], data[i - 1]) << i;
  EXPECT_EQ(e.replies[134], data[127]);
  EXPECT_EQ((V(e.replies.begin() + 135, e.replies.end())), (V{0x5C, 0x5D, 0x47}));
  EXPECT_EQ(e.acks, acks_but_last(138));
  EXPECT_EQ(card.flag(), 0x00);  // bit 3 cleared by the write

  auto r = command(card, read_bytes(sector));
  EXPECT_EQ(r.replies[1], 0x00);  // FLAG
  EXPECT_EQ(r.replies[8], 0x01);  // confirmed address
  EXPECT_EQ(r.replies[9], 0x23);
  EXPECT_EQ((V(r.replies.begin() + 10, r.replies.begin() + 138)), data);
  u8 chk = 0x01 ^ 0x23;
  for (u8 d : data) chk ^= d;
  EXPECT_EQ(r.replies[138], chk);
  EXPECT_EQ(r.replies[139], 0x47);
}

TEST(MemcardProtocol, BadChecksumIsRefused) {
  MemoryCard card;
  const V before = read_sector_data(card, 0x40);
  auto e = command(card, write_bytes(0x40, pattern(0x22), 1));
  EXPECT_EQ(e.replies.back(), 0x4E);
  EXPECT_EQ(read_sector_data(card, 0x40), before);
  EXPECT_EQ(card.flag(), 0x08);
  EXPECT_FALSE(card.dirty());
}

TEST(MemcardProtocol, BadSectorWriteEndsWithFF) {
  MemoryCard card;
  auto e = command(card, write_bytes(0x0400, pattern(0x33)));
  EXPECT_EQ(e.replies.back(), 0xFF);
  EXPECT_FALSE(card.dirty());
}

TEST(MemcardProtocol, BadSectorReadStopsAfterFFFF) {
  MemoryCard card;
  auto e = command(card, read_bytes(0x0400));
  EXPECT_EQ(e.replies[8], 0xFF);
  EXPECT_EQ(e.replies[9], 0xFF);
  EXPECT_TRUE(e.acks[8]);
  EXPECT_FALSE(e.acks[9]);
  EXPECT_EQ(e.replies[10], 0xFF);
  EXPECT_FALSE(e.acks[10]);
}

TEST(MemcardProtocol, UnknownCommandRepliesFlagWithoutAck) {
  MemoryCard card;
  auto e = command(card, {0x81, 0x58, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0x08, 0xFF}));
  EXPECT_EQ(e.acks, (std::vector<bool>{true, false, false}));
}

TEST(MemcardProtocol, ReadHasLateAckAfterSeventhByte) {
  MemoryCard card;
  card.deselect();
  const V bytes = read_bytes(0);
  for (size_t i = 0; i < 8; ++i) {
    card.transfer(bytes[i]);
    const Cycles expected = i == 6 ? MemoryCard::kAckDelay + 31000 : MemoryCard::kAckDelay;
    EXPECT_EQ(card.ack_delay(), expected) << i;
  }
}

// --- image files ----------------------------------------------------------------------------

class MemcardFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(PSXRL_BUILD_DIR) / "memcard_test" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  fs::path dir_;
};

void write_file(const fs::path& p, const V& bytes) {
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

V read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return V(std::istreambuf_iterator<char>(f), {});
}

TEST_F(MemcardFile, WrongSizeIsRefusedNamingFileAndSizes) {
  const fs::path p = dir_ / "short.mcd";
  write_file(p, V(1000, 0));
  try {
    MemoryCard card(p);
    FAIL() << "no error";
  } catch (const MemoryCardError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(p.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("1000"), std::string::npos) << msg;
    EXPECT_NE(msg.find("131072"), std::string::npos) << msg;
  }
  EXPECT_EQ(fs::file_size(p), 1000u);  // left untouched
}

TEST_F(MemcardFile, DirectoryIsRefused) {
  const fs::path p = dir_ / "card.mcd";
  fs::create_directory(p);
  EXPECT_THROW(MemoryCard card(p), MemoryCardError);
}

// A card file the user may not read is refused, naming it. Root reads any file, and CI runs as
// root: there the attempt runs in a child process that has become an ordinary user (uid and gid
// 65534, "nobody"), so the refusal is tested as root too. The file lies under the temporary
// directory, which every user can enter (the build tree may sit in a home only root can).
TEST_F(MemcardFile, UnreadableFileIsRefused) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("psxrl_memcard_unreadable_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::permissions(dir, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  const fs::path p = dir / "locked.mcd";
  write_file(p, V(MemoryCard::kSize, 0));
  fs::permissions(p, fs::perms::none);
  EXPECT_EXIT(
      {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) {
          std::fprintf(stderr, "cannot become uid 65534\n");
          std::_Exit(2);
        }
        try {
          MemoryCard card(p);
          std::fprintf(stderr, "no error\n");
          std::_Exit(1);
        } catch (const MemoryCardError& e) {
          std::fprintf(stderr, "%s\n", e.what());
          std::_Exit(0);
        }
      },
      ::testing::ExitedWithCode(0), "locked\\.mcd.*: cannot open: Permission denied");
  fs::remove_all(dir);
}

TEST_F(MemcardFile, ExistingImageIsLoaded) {
  const fs::path p = dir_ / "card.mcd";
  V image(MemoryCard::kSize);
  for (size_t i = 0; i < image.size(); ++i) image[i] = static_cast<u8>(i * 7 + (i >> 8));
  write_file(p, image);
  MemoryCard card(p);
  const u16 sector = 0x2A5;
  EXPECT_EQ(read_sector_data(card, sector),
            V(image.begin() + sector * 128, image.begin() + sector * 128 + 128));
  EXPECT_FALSE(card.dirty());
}

TEST_F(MemcardFile, FileIsCreatedOnFirstWriteOnly) {
  const fs::path p = dir_ / "new.mcd";
  {
    MemoryCard card(p);
    read_sector_data(card, 0);
    command(card, {0x81, 0x53, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00});
    EXPECT_FALSE(fs::exists(p));
    command(card, write_bytes(0x3F, pattern(0x44)));
    ASSERT_TRUE(fs::exists(p));
    EXPECT_FALSE(card.dirty());
    EXPECT_EQ(read_file(p), card.data());
    EXPECT_FALSE(test::temporary_files_left(dir_ / "new.mcd"));
  }
  MemoryCard again(p);
  EXPECT_EQ(read_sector_data(again, 0x3F), pattern(0x44));
  EXPECT_EQ(again.flag(), 0x08);  // FLAG is power-up state, not part of the image
}

TEST_F(MemcardFile, CardWithoutReadsOrWritesLeavesNoFile) {
  const fs::path p = dir_ / "untouched.mcd";
  { MemoryCard card(p); }
  EXPECT_FALSE(fs::exists(p));
}

// A write that fails part-way (here the file size limit, which binds root too, in a child
// process) leaves the old image intact and no temporary file, names the card and the reason, and
// the card stays dirty so that a later flush saves the change.
TEST_F(MemcardFile, FailedWriteLeavesOldFileIntactAndRetries) {
  const fs::path p = dir_ / "card.mcd";
  V image(MemoryCard::kSize, 0x5A);
  write_file(p, image);
  MemoryCard card(p);
  EXPECT_EXIT(
      {
        rlimit limit;
        if (!test::limit_file_size(4096, limit)) std::_Exit(2);
        command(card, write_bytes(0x10, pattern(0x55)));  // its save fails: the card stays dirty
        try {
          card.flush();
          std::_Exit(3);
        } catch (const MemoryCardError& e) {
          std::fprintf(stderr, "%s\n", e.what());
        }
        if (!card.dirty() || read_file(p) != image || test::temporary_files_left(p)) std::_Exit(4);
        ::setrlimit(RLIMIT_FSIZE, &limit);
        card.flush();
        V on_disk = read_file(p);
        if (card.dirty() || V(on_disk.begin() + 0x10 * 128, on_disk.begin() + 0x11 * 128) != pattern(0x55))
          std::_Exit(5);
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(0), "memory card .*card\\.mcd: write failed: File too large");
}

TEST(MemcardState, RoundTripKeepsContentsFlagAndDirty) {
  MemoryCard a;
  command(a, write_bytes(0x200, pattern(0x77)));
  test::clock_bytes(a, {0x81, 0x52, 0x00, 0x00, 0x02, 0x00, 0x00});  // mid read
  StateIO w;
  a.do_state(w);
  MemoryCard b;
  StateIO r(w.buffer().data(), w.buffer().size());
  b.do_state(r);
  EXPECT_TRUE(r.at_end());
  EXPECT_EQ(b.data(), a.data());
  EXPECT_EQ(b.flag(), 0x00);
  EXPECT_TRUE(b.dirty());
  V rest(3 + 128 + 2, 0x00);
  EXPECT_EQ(test::clock_bytes(b, rest).replies, test::clock_bytes(a, rest).replies);
}

// A state is user input: one claiming a read in progress past the card's last sector (which the
// protocol never reaches) must be refused, not read beyond the image (a fuzz_memcard crash).
TEST(MemcardState, ReadInProgressBeyondTheCardIsRefused) {
  MemoryCard a;
  test::clock_bytes(a, {0x81, 0x52, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00});  // in the data
  StateIO w;
  a.do_state(w);
  V blob = w.buffer();
  // After the section header (tag, version, length), data, flag, dirty, step, mode.
  const size_t sector_at = 12 + MemoryCard::kSize + 7;
  ASSERT_EQ(blob[sector_at], 0x00);
  ASSERT_EQ(blob[sector_at + 1], 0x02);
  blob[sector_at] = 0x00, blob[sector_at + 1] = 0x04;  // sector 0400h, one past the last
  MemoryCard b;
  StateIO r(blob.data(), blob.size());
  EXPECT_THROW(b.do_state(r), StateError);
}

}  // namespace
}  // namespace psx
