// Save states, determinism and isolation (issue 8): the same inputs give the same bits; "save at
// f, run n" equals "load into a fresh console, run n"; 8 consoles on 8 threads equal each run
// alone; broken state files are refused, each with its own message, leaving the console as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <thread>

#include "core/console.h"
#include "core/endian.h"
#include "core/hash.h"
#include "core/save_state.h"
#include "temp_files.h"

namespace psx {
namespace {

const std::string kProgram = PSXRL_BUILD_DIR "/bench/cpu_loop.exe";
// The built-in game: GTE, GPU by DMA, SPU, pad and timers all in use.
const std::string kGame = PSXRL_BUILD_DIR "/games/tumble/tumble.exe";

// RAM, scratchpad, VRAM, the displayed frame, the cycle count, and the audio produced since the
// last call (taken from the console).
u64 console_hash(Console& c) {
  u64 h = fnv1a(c.ram().data(), c.ram().size());
  h = fnv1a(c.scratchpad().data(), c.scratchpad().size(), h);
  h = fnv1a(c.vram(), Console::kVramWidth * Console::kVramHeight * 2, h);
  Console::Frame f = c.frame();
  h = fnv1a(f.rgb, size_t(f.width) * f.height * 3, h);
  std::vector<StereoSample> audio;
  c.take_audio(audio);
  h = fnv1a(audio.data(), audio.size() * sizeof(StereoSample), h);
  u64 cyc = c.cycles();
  return fnv1a(&cyc, sizeof cyc, h);
}

// Presses that drive the game from the title into play: the same for every run.
void scripted_input(Console& c, int frame) {
  if (frame == 20) c.press_for(1, pad_button::kStart, 3);
  if (frame == 40) c.press_for(1, pad_button::kCross, 3);
  if (frame >= 60 && frame % 25 == 0) c.press_for(1, frame % 50 ? pad_button::kUp : pad_button::kRight, 4);
}

std::vector<u64> frame_hashes(const std::string& exe, int frames) {
  Console c;
  c.boot_exe(exe);
  std::vector<u64> out;
  for (int f = 0; f < frames; ++f) {
    scripted_input(c, f);
    c.run_frame();
    out.push_back(console_hash(c));
  }
  return out;
}

TEST(Determinism, SameProgramSameHashesEveryFrame) {
  for (const std::string& exe : {kProgram, kGame}) {
    SCOPED_TRACE(exe);
    auto a = frame_hashes(exe, 150), b = frame_hashes(exe, 150);
    EXPECT_EQ(a, b);
    EXPECT_NE(a[100], a[149]);  // the program does change state
  }
}

// "Save at frame f, run n more frames (with the same inputs)" equals "load the state made at f
// into a fresh console, run n frames", hash for hash, frame for frame.
void round_trips(const std::string& exe, u32 seed, int trials, int max_f) {
  for (int trial = 0; trial < trials; ++trial) {
    seed = seed * 1103515245 + 12345;  // frame numbers from a fixed LCG: repeatable
    int f = 1 + int((seed >> 16) % u32(max_f)), n = 1 + int((seed >> 8) % 30);
    SCOPED_TRACE(exe + ": save at frame " + std::to_string(f) + ", run " + std::to_string(n));
    Console a;
    a.boot_exe(exe);
    for (int i = 0; i < f; ++i) {
      scripted_input(a, i);
      a.run_frame();
    }
    console_hash(a);  // takes the audio made so far
    std::vector<u8> blob = a.save_state(trial % 2 == 0);
    Console b;
    b.boot_exe(exe);
    b.load_state(blob);
    for (int i = f; i < f + n; ++i) {
      scripted_input(a, i);
      scripted_input(b, i);
      a.run_frame();
      b.run_frame();
      ASSERT_EQ(console_hash(a), console_hash(b)) << "frame " << i;
    }
    EXPECT_EQ(a.frames(), b.frames());
    EXPECT_EQ(a.instructions(), b.instructions());
  }
}

TEST(SaveState, RoundTripGivesTheSameFuture) { round_trips(kProgram, 12345, 4, 40); }

TEST(SaveState, RoundTripOnTheBuiltInGame) { round_trips(kGame, 777, 6, 300); }

TEST(Isolation, EightThreadsMatchOneAlone) {
  auto alone = frame_hashes(kGame, 90);
  std::vector<std::vector<u64>> results(8);
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i) threads.emplace_back([&results, i] { results[i] = frame_hashes(kGame, 90); });
  for (auto& t : threads) t.join();
  for (const auto& r : results) EXPECT_EQ(r, alone);
}

class BadState : public ::testing::Test {
 protected:
  void SetUp() override {
    c.boot_exe(kProgram);
    c.run_frames(3);
    good = c.save_state();
    c.run_frames(2);
    console_hash(c);  // takes the audio made so far, so the next hashes see none
    before = console_hash(c);
  }
  std::string load_error(const std::vector<u8>& blob) {
    try {
      c.load_state(blob);
    } catch (const StateError& e) {
      EXPECT_EQ(console_hash(c), before) << "a failed load changed the console";
      return e.what();
    }
    return "";
  }
  Console c;
  std::vector<u8> good;
  u64 before = 0;
};

TEST_F(BadState, EachDefectHasItsOwnMessage) {
  std::vector<u8> truncated(good.begin(), good.end() - 100);
  EXPECT_NE(load_error(truncated).find("truncated or padded"), std::string::npos);
  std::vector<u8> short_header(good.begin(), good.begin() + 20);
  EXPECT_NE(load_error(short_header).find("truncated header"), std::string::npos);
  std::vector<u8> flipped = good;
  flipped[SaveStateHeader::kSize + 5000] ^= 0x10;
  EXPECT_NE(load_error(flipped).find("checksum mismatch"), std::string::npos);
  std::vector<u8> version = good;
  version[8] = 99;
  EXPECT_NE(load_error(version).find("format version 99"), std::string::npos);
  std::vector<u8> not_state(100, 'x');
  EXPECT_NE(load_error(not_state).find("not a psxrl save state"), std::string::npos);

  Console other;  // another program: its states do not belong to this console
  other.boot_exe(PSXRL_BUILD_DIR "/tests/roms/hello.exe");
  EXPECT_NE(load_error(other.save_state()).find("different disc or EXE"), std::string::npos);

  std::vector<u8> bios(Bus::kBiosSize, 0);
  Console with_bios;
  with_bios.load_bios_image(bios, "zero.bin");
  with_bios.boot_exe(kProgram);
  EXPECT_NE(load_error(with_bios.save_state()).find("different BIOS"), std::string::npos);
}

// Offset of a section's header (4 tag bytes, u32 version, u32 length) in a payload.
size_t section_at(const std::vector<u8>& payload, const char (&tag)[5]) {
  auto it = std::search(payload.begin(), payload.end(), tag, tag + 4);
  EXPECT_NE(it, payload.end()) << tag;
  return size_t(it - payload.begin());
}

// A load that fails after the scheduler's time was read puts the backup back without running the
// lazily stepped devices up to that time: here the clock is 0xFFFF0000 SPU samples (768 cycles
// each) ahead and the SPU's section has a version this build refuses, so catching the SPU up first would
// make 4.3 billion samples, one by one with SPU IRQ9 enabled (psx-spx SPUCNT bit 6), before the
// refusal.
TEST(SaveState, RefusedStateWithAFarLaterClockLeavesTheConsoleAsItWas) {
  Console c;
  c.boot_exe(kGame);
  c.run_frames(10);
  u32 spucnt = 0;
  ASSERT_TRUE(c.bus().read16(0x1F801DAA, spucnt));
  ASSERT_TRUE(c.bus().write16(0x1F801DA4, 0xFFFF));  // IRQ address 7FFF8h, not reached here
  ASSERT_TRUE(c.bus().write16(0x1F801DAA, spucnt | 0x8040));  // SPU enable, IRQ9 enable
  const std::vector<u8> good = c.save_state();
  SaveStateHeader h;
  h.bios_hash = u64(load_le32(&good[16])) | u64(load_le32(&good[20])) << 32;
  h.program_hash = u64(load_le32(&good[24])) | u64(load_le32(&good[28])) << 32;
  std::vector<u8> p = unpack_save_state(good.data(), good.size(), h.bios_hash, h.program_hash);
  const size_t now_at = section_at(p, "SCHD") + 12;  // SCHD's first field: the time, u64
  const u64 later = (u64(load_le32(&p[now_at])) | u64(load_le32(&p[now_at + 4])) << 32) + 0xFFFF0000ull * 768;
  store_le32(&p[now_at], u32(later));
  store_le32(&p[now_at + 4], u32(later >> 32));
  p[section_at(p, "SPU ") + 4] = 99;  // a section version this build does not read
  EXPECT_THROW(c.load_state(pack_save_state(h, p)), StateError);
  EXPECT_TRUE(c.save_state() == good) << "the refused state changed the console";
}

// A GTE command ends at most 44 cycles after it starts (NCDT, psx-spx "GTE Command Summary"), so
// a state whose GTE is busy until later than 44 cycles past its time cannot come from a console;
// the recompiler's deadline budget (block_emitter.cpp) counts on that bound.
TEST(SaveState, GteBusyBeyondItsLongestCommandIsRefused) {
  Console c;
  c.boot_exe(kProgram);
  c.run_frames(2);
  const std::vector<u8> good = c.save_state();
  SaveStateHeader h;
  h.bios_hash = u64(load_le32(&good[16])) | u64(load_le32(&good[20])) << 32;
  h.program_hash = u64(load_le32(&good[24])) | u64(load_le32(&good[28])) << 32;
  std::vector<u8> p = unpack_save_state(good.data(), good.size(), h.bios_hash, h.program_hash);
  const size_t now_at = section_at(p, "SCHD") + 12;
  const u64 now = u64(load_le32(&p[now_at])) | u64(load_le32(&p[now_at + 4])) << 32;
  // The CPU section's fields: 32 registers, HI, LO, pc, next_pc, current_pc (148 bytes), two
  // delay-slot flags (2), the load delay's four words (16), then the multiply's and the GTE's
  // end times (u64 each).
  const size_t gte_at = section_at(p, "CPU ") + 12 + 148 + 2 + 16 + 8;
  for (const u64 busy_until : {now + 44, now + 45}) {
    store_le32(&p[gte_at], u32(busy_until));
    store_le32(&p[gte_at + 4], u32(busy_until >> 32));
    if (busy_until == now + 44) {
      EXPECT_NO_THROW(c.load_state(pack_save_state(h, p)));
    } else {
      try {
        c.load_state(pack_save_state(h, p));
        ADD_FAILURE() << "a GTE busy 45 cycles ahead was loaded";
      } catch (const StateError& e) {
        EXPECT_NE(std::string(e.what()).find("too far ahead"), std::string::npos) << e.what();
      }
    }
  }
}

TEST_F(BadState, FilesAreWrittenAtomicallyAndReadBack) {
  std::string path = ::testing::TempDir() + "/psxrl_state_test.sav";
  c.save_state_file(path);
  EXPECT_FALSE(test::temporary_files_left(path));
  u64 saved = console_hash(c);
  c.run_frames(2);
  c.load_state_file(path);
  EXPECT_EQ(console_hash(c), saved);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace psx
