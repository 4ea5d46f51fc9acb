// Helpers for the Tumble tests on the emulated console: boot the built tumble.exe (from the EXE or
// from the disc image mkdisc made of it), read and write the RAM contract at 0x80010000 (README.md
// "RAM contract"), press pad buttons through the Console API, save screenshots into the build tree.
#pragma once
#include <gtest/gtest.h>

#include <cstddef>
#include <string>

#include "contract.h"
#include "core/console.h"
#include "core/sio/pad.h"

namespace tumble_test {

constexpr psx::u32 kContractAddress = 0x80010000;

#define TUMBLE_FIELD(name) static_cast<psx::u32>(offsetof(TumbleContract, name))

enum class Boot { Exe, Disc };

// Workloads the bit-identity tests (idle skipping, the recompiler) run under two configurations:
// level 1 started through the contract, then six right/up rolls with the game's frames between.
inline void play_level_one_moves(psx::Console& c) {
  c.run_frames(200);
  c.write32(kContractAddress + TUMBLE_FIELD(request_level), 1);
  for (int i = 0; i < 6; ++i) {
    c.press_for(1, psx::pad_button::kRight, 8);
    c.run_frames(30);
    c.press_for(1, psx::pad_button::kUp, 8);
    c.run_frames(30);
  }
}

// The cdboot test ROM as BIOS booting Tumble's disc through the emulated drive.
inline void boot_disc_with_cdboot_rom(psx::Console& c) {
  c.load_bios(PSXRL_BUILD_DIR "/tests/roms/cdboot_rom.bin");
  c.insert_disc(TUMBLE_CUE);
  c.boot_disc();
}

struct TumbleConsole {
  psx::Console console;

  explicit TumbleConsole(Boot boot = Boot::Exe, const char* bios = nullptr, bool dualshock = false) {
    if (bios) console.load_bios(bios);
    if (dualshock) console.plug_pad(1, psx::Console::PadType::DualShock);
    if (boot == Boot::Exe) {
      console.boot_exe(TUMBLE_EXE);
    } else {
      console.insert_disc(TUMBLE_CUE);
      console.boot_disc();
    }
  }

  psx::u32 word(psx::u32 offset) const { return console.read32(kContractAddress + offset); }
  void set_word(psx::u32 offset, psx::u32 v) { console.write32(kContractAddress + offset, v); }
  psx::u32 state() const { return word(TUMBLE_FIELD(state)); }

  // Runs emulated frames until the game has run `n` more frames of its own (bounded).
  bool run_game_frames(psx::u32 n) {
    psx::u32 target = word(TUMBLE_FIELD(frame)) + n;
    for (int i = 0; i < 4000 && word(TUMBLE_FIELD(frame)) < target; ++i) console.run_frame();
    return word(TUMBLE_FIELD(frame)) >= target && !console.stopped();
  }

  // Boots to the title (magic written, state 50), then starts level `n` through the request
  // variable: one game frame later it is in play with a full clock.
  bool start_level(psx::u32 n) {
    for (int i = 0; i < 600 && word(TUMBLE_FIELD(magic)) != TUMBLE_MAGIC; ++i) console.run_frame();
    if (!run_game_frames(1)) return false;
    set_word(TUMBLE_FIELD(request_level), n);
    return run_game_frames(1) && state() == STATE_PLAYING && word(TUMBLE_FIELD(level)) == n;
  }

  // One move by the pad: holds `buttons` until the game has taken the move (or left play), then
  // lets go and runs until the move has finished (or play ended). Returns the game frames used.
  psx::u32 move(psx::u16 buttons) {
    psx::u32 f0 = word(TUMBLE_FIELD(frame));
    console.press(1, buttons);
    for (int i = 0; i < 10 && word(TUMBLE_FIELD(move)) == MOVE_NONE && state() == STATE_PLAYING; ++i)
      console.run_frame();
    console.release(1, buttons);
    for (int i = 0; i < 200 && word(TUMBLE_FIELD(move)) != MOVE_NONE && state() == STATE_PLAYING; ++i)
      console.run_frame();
    return word(TUMBLE_FIELD(frame)) - f0;
  }

  // Presses `buttons` for one game frame (a menu choice), then runs one more with none held.
  void tap(psx::u16 buttons) {
    console.press(1, buttons);
    run_game_frames(1);
    console.release(1, buttons);
    run_game_frames(1);
  }

  // Saves the displayed picture as build/tests/tumble_<name>.png (look at them).
  void screenshot(const std::string& name) {
    EXPECT_NO_THROW(console.save_screenshot(std::string(PSXRL_BUILD_DIR) + "/tests/tumble_" + name + ".png"));
  }
};

// Route letters as in tumble_rules_test.cpp: F forward, L look left, R look right, J jump forward,
// H jump in place.
inline psx::u16 route_buttons(char c) {
  switch (c) {
    case 'F': return psx::pad_button::kUp;
    case 'L': return psx::pad_button::kLeft;
    case 'R': return psx::pad_button::kRight;
    case 'J': return psx::pad_button::kCross | psx::pad_button::kUp;
    default: return psx::pad_button::kCross;
  }
}

}  // namespace tumble_test
