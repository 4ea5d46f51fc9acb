// In-memory snapshots (Console::snapshot/restore) are the environments' fast reset: restoring one
// must leave the console exactly as loading the equivalent save state does, so that a reset
// followed by N frames or moves equals the first run, bit for bit (compared as whole save
// states). A snapshot of another program is refused without touching the console.
#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include "core/console.h"
#include "core/state.h"
#include "rl/env.h"

namespace {

using psx::Console;

TEST(ConsoleSnapshot, RestoreThenRunRepeatsTheRunExactly) {
  Console c;
  c.boot_exe(TUMBLE_EXE);
  c.run_frames(90);
  Console::Snapshot snap;
  c.snapshot(snap);
  const std::vector<psx::u8> at_snapshot = c.save_state(false);
  c.press_for(1, psx::pad_button::kStart, 4);
  c.run_frames(60);
  const std::vector<psx::u8> first = c.save_state(false);

  c.restore(snap);
  EXPECT_TRUE(c.save_state(false) == at_snapshot);
  c.press_for(1, psx::pad_button::kStart, 4);
  c.run_frames(60);
  EXPECT_TRUE(c.save_state(false) == first);

  // Taking a snapshot again into the same object replaces it.
  c.snapshot(snap);
  c.run_frames(5);
  c.restore(snap);
  EXPECT_TRUE(c.save_state(false) == first);
}

// A restore passes over VRAM where VRAM still is what the snapshot holds (Gpu::vram_token()):
// nothing drawn since, or only draws still waiting in the deferred queue, which the restore drops.
// Draws made since, by a read of VRAM that runs the queue, or a console that never held the
// snapshot's VRAM, must still get the snapshot's VRAM back.
TEST(ConsoleSnapshot, RestoreGivesBackVramWhateverWasDrawnSince) {
  Console c, other;
  c.boot_exe(TUMBLE_EXE);
  other.boot_exe(TUMBLE_EXE);
  c.set_pixels_observed(false);  // draws wait in the queue
  c.run_frames(60);
  Console::Snapshot snap;
  c.snapshot(snap);
  const std::vector<psx::u8> at_snapshot = c.save_state(false);
  const std::vector<psx::u16> vram(c.vram(), c.vram() + Console::kVramWidth * Console::kVramHeight);

  c.run_frames(20);  // queued only
  c.restore(snap);
  EXPECT_TRUE(c.save_state(false) == at_snapshot);

  c.run_frames(20);
  ASSERT_FALSE(std::equal(vram.begin(), vram.end(), c.vram()));  // the read draws the queue
  c.restore(snap);
  EXPECT_TRUE(std::equal(vram.begin(), vram.end(), c.vram()));
  EXPECT_TRUE(c.save_state(false) == at_snapshot);

  other.run_frames(75);
  other.restore(snap);
  EXPECT_TRUE(other.save_state(false) == at_snapshot);
}

// A restore copies back only the pages of RAM and the scratchpad written since the snapshot
// (core/written_pages.h), so every way of writing them must mark its page. cpu_memory stores to
// both through every width and several mirrors: under the recompiler its stores are native code,
// under the interpreter they go through the bus. The host writes both. The restored console must
// be the snapshot's again, byte for byte.
TEST(ConsoleSnapshot, RestoreUndoesWritesOfEveryKind) {
  for (const Console::CpuMode mode : {Console::CpuMode::Recompiler, Console::CpuMode::Interpreter}) {
    SCOPED_TRACE(mode == Console::CpuMode::Recompiler ? "recompiler" : "interpreter");
    Console c;
    c.set_cpu_mode(mode);
    c.boot_exe(PSXRL_BUILD_DIR "/tests/roms/cpu_memory.exe");
    Console::Snapshot snap;
    c.snapshot(snap);
    const std::vector<psx::u8> at_snapshot = c.save_state(false);
    const auto before = std::as_const(c).scratchpad();
    const std::vector<psx::u8> scratch(before.begin(), before.end());
    c.run_until([&] { return c.stopped(); }, 600);
    ASSERT_EQ(c.exit_code(), 0u);
    const auto now = std::as_const(c).scratchpad();
    ASSERT_FALSE(std::equal(scratch.begin(), scratch.end(), now.begin()));  // the program wrote it
    c.restore(snap);
    EXPECT_TRUE(c.save_state(false) == at_snapshot);

    c.write8(0x80123456, 0x5A);
    c.write16(0xA0001002, 0x1234);
    c.write32(0x1F8003FC, 0xCAFEF00D);
    c.restore(snap);
    EXPECT_TRUE(c.save_state(false) == at_snapshot);
  }
}

// RAM lent for writing in place (Console::ram()) is written unseen, so restores copy it whole
// from then on, even for a snapshot taken after the lending.
TEST(ConsoleSnapshot, RestoreUndoesWritesThroughLentRam) {
  Console c;
  c.boot_exe(TUMBLE_EXE);
  c.run_frames(30);
  const std::span<psx::u8> ram = c.ram(), scratch = c.scratchpad();
  Console::Snapshot snap;
  c.snapshot(snap);
  const std::vector<psx::u8> at_snapshot = c.save_state(false);
  ram[0x1F0000] ^= 0xFF;
  scratch[0x10] ^= 0xFF;
  c.restore(snap);
  EXPECT_TRUE(c.save_state(false) == at_snapshot);
}

// The pages nobody wrote are left alone: a write the bus never hears of (made here straight into
// the bus's RAM, as no user can) survives the restore, while a reported one beside it is undone.
// Without this a restore would still be correct, only no faster.
TEST(ConsoleSnapshot, RestoreLeavesPagesNotWrittenAlone) {
  Console c;
  c.boot_exe(TUMBLE_EXE);
  c.run_frames(30);
  Console::Snapshot snap;
  c.snapshot(snap);
  const psx::u8 unseen = c.bus().ram()[0x1F0000], seen = c.bus().ram()[0x1F0100];
  c.bus().ram()[0x1F0000] = unseen ^ 0xFF;
  c.write8(0x801F0100, seen ^ 0xFF);
  c.restore(snap);
  EXPECT_EQ(c.bus().ram()[0x1F0000], unseen ^ 0xFF);
  EXPECT_EQ(c.bus().ram()[0x1F0100], seen);
}

TEST(ConsoleSnapshot, RestoreMatchesLoadState) {
  Console a, b;
  a.boot_exe(TUMBLE_EXE);
  b.boot_exe(TUMBLE_EXE);
  a.run_frames(40);
  Console::Snapshot snap;
  a.snapshot(snap);
  const std::vector<psx::u8> blob = a.save_state(false);
  b.run_frames(7);
  a.run_frames(3);
  a.restore(snap);
  b.load_state(blob);
  a.run_frames(30);
  b.run_frames(30);
  EXPECT_TRUE(a.save_state(false) == b.save_state(false));
}

TEST(ConsoleSnapshot, OtherProgramOrEmptySnapshotIsRefused) {
  Console tumble, other;
  tumble.boot_exe(TUMBLE_EXE);
  other.boot_exe(PSXRL_BUILD_DIR "/tests/roms/hello.exe");
  tumble.run_frames(5);
  other.run_frames(5);
  Console::Snapshot snap;
  EXPECT_THROW(tumble.restore(snap), psx::StateError);
  other.snapshot(snap);
  const std::vector<psx::u8> before = tumble.save_state(false);
  EXPECT_THROW(tumble.restore(snap), psx::StateError);
  EXPECT_TRUE(tumble.save_state(false) == before);
}

// An environment's reset restores its boot snapshot: a reset after an episode and the same
// actions end in the same machine as a fresh environment's first episode: RAM, VRAM, CPU
// registers, cycle and instruction counts. (Whole save-state bytes are not compared here: the
// GPU's state holds a struct's padding bytes, whose content depends on the host's memory
// history, and the two environments have different histories.)
TEST(ConsoleSnapshot, EnvResetThenStepsEqualsFreshEnv) {
  psxrl::rl::EnvConfig config;
  config.obs = "simple";
  psxrl::rl::Env used(config), fresh(config);
  const int actions[] = {0, 1, 1, 2, 3, 0, 2, 1};
  used.reset(1, 5);
  for (int a : actions)
    if (!used.episode_over()) used.step(a);
  used.reset(1, 9);
  fresh.reset(1, 9);
  int steps = 0;
  for (int a : actions) {
    if (fresh.episode_over()) break;
    const psxrl::rl::StepResult r1 = used.step(a), r2 = fresh.step(a);
    EXPECT_EQ(r1.reward, r2.reward);
    EXPECT_EQ(r1.terminated, r2.terminated);
    ++steps;
  }
  EXPECT_GE(steps, 2);
  Console &u = used.console(), &f = fresh.console();
  EXPECT_EQ(u.cycles(), f.cycles());
  EXPECT_EQ(u.instructions(), f.instructions());
  EXPECT_EQ(u.frames(), f.frames());
  EXPECT_TRUE(std::equal(u.ram().begin(), u.ram().end(), f.ram().begin()));
  EXPECT_TRUE(std::equal(u.vram(), u.vram() + Console::kVramWidth * Console::kVramHeight, f.vram()));
  for (psx::u32 r = 0; r < 32; ++r) EXPECT_EQ(u.cpu().reg(r), f.cpu().reg(r)) << "r" << r;
  EXPECT_EQ(u.cpu().pc(), f.cpu().pc());
}

}  // namespace
