// Save states are user files: a state whose payload was altered but whose checksum was made to
// match (a hand-edited or maliciously built file) must either load or be refused with a
// StateError that leaves the console unchanged; a state that loads must define the console's
// whole future (the same in any console that loads it), and running it must not crash the host.
#include <gtest/gtest.h>

#include "core/console.h"
#include "core/endian.h"
#include "core/save_state.h"

namespace psx {
namespace {

TEST(SaveStateFuzz, AlteredPayloadsNeverCrash) {
  const std::string game = PSXRL_BUILD_DIR "/games/tumble/tumble.exe";
  Console source;
  source.boot_exe(game);
  source.run_frames(90);
  std::vector<u8> blob = source.save_state();
  SaveStateHeader h;
  h.bios_hash = u64(load_le32(&blob[16])) | u64(load_le32(&blob[20])) << 32;
  h.program_hash = u64(load_le32(&blob[24])) | u64(load_le32(&blob[28])) << 32;
  const std::vector<u8> payload = unpack_save_state(blob.data(), blob.size(), h.bios_hash, h.program_hash);

  // The unaltered payload, repacked, is the control: it loads and gives the source's future.
  {
    Console c;
    c.boot_exe(game);
    c.load_state(pack_save_state(h, payload));
    Console reference;
    reference.boot_exe(game);
    reference.load_state(blob);
    c.run_frames(2);
    reference.run_frames(2);
    ASSERT_EQ(c.save_state(), reference.save_state()) << "the repacked unaltered payload differs";
  }

  // A console that has run elsewhere: a state that loads must replace all of its state, so after
  // the same frames it matches a freshly booted console that loaded the same state.
  Console elsewhere;
  elsewhere.boot_exe(game);
  elsewhere.run_frames(30);

  u32 seed = 2024;
  auto next = [&seed] { return seed = seed * 1664525 + 1013904223; };
  int loaded = 0, refused = 0;
  for (int trial = 0; trial < 120; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::vector<u8> p = payload;
    // Small edits anywhere, biased towards the device state after RAM, VRAM and sound RAM.
    int edits = 1 + int(next() % 8);
    for (int e = 0; e < edits; ++e) {
      size_t at = next() % 4 == 0 ? next() % p.size() : p.size() - 1 - next() % 65536;
      p[at] = u8(next() >> 24);
    }
    const std::vector<u8> state = pack_save_state(h, p);
    Console c;
    c.boot_exe(game);
    const std::vector<u8> before = c.save_state();
    try {
      c.load_state(state);
    } catch (const StateError& e) {
      // Refused: a message saying where, and the console exactly as it was (console.h).
      ++refused;
      EXPECT_EQ(std::string(e.what()).rfind("save state", 0), 0u) << e.what();
      EXPECT_TRUE(c.save_state() == before) << "a refused state changed the console: " << e.what();
      continue;
    }
    ++loaded;
    elsewhere.load_state(state);  // must load wherever it loaded once
    c.run_frames(2);  // whatever the state held, running it is guest behaviour
    elsewhere.run_frames(2);
    EXPECT_TRUE(c.save_state() == elsewhere.save_state())
        << "the same state gave different futures in a fresh console and one that had run";
  }
  // Both outcomes must be exercised, or the edits no longer reach what they are meant to test.
  EXPECT_GT(loaded, 0);
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace psx
