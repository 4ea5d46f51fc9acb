// Save states are user files: a state whose payload was altered but whose checksum was made to
// match (a hand-edited or maliciously built file) must either load or be refused with a
// StateError, and a console that loaded one must keep running without crashing the host.
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

  u32 seed = 2024;
  auto next = [&seed] { return seed = seed * 1664525 + 1013904223; };
  int loaded = 0, refused = 0;
  for (int trial = 0; trial < 120; ++trial) {
    std::vector<u8> p = payload;
    // Small edits anywhere, biased towards the device state after RAM, VRAM and sound RAM.
    int edits = 1 + int(next() % 8);
    for (int e = 0; e < edits; ++e) {
      size_t at = next() % 4 == 0 ? next() % p.size() : p.size() - 1 - next() % 65536;
      p[at] = u8(next() >> 24);
    }
    Console c;
    c.boot_exe(game);
    try {
      c.load_state(pack_save_state(h, p));
      ++loaded;
    } catch (const StateError&) {
      ++refused;
      continue;
    }
    c.run_frames(2);  // whatever the state held, running it is guest behaviour
  }
  EXPECT_EQ(loaded + refused, 120);
}

}  // namespace
}  // namespace psx
