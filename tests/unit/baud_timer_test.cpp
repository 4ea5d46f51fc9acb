// The serial ports' baud timer (core/sio/baud_timer.h; psx-spx "Serial Interfaces (SIO)"): it
// reloads with BAUD * factor / 2 when BAUD is written and counts down at the CPU clock, so
// `elapsed` cycles after the write it reads half - elapsed % half (half = the reload value), at
// SIO#_STAT bits 11-31. The timer keeps the phase of its latest read; these reads come close
// together, far apart (past 2^32 cycles), backwards after a state load, and across a factor
// change, and each must still be that arithmetic.
#include <gtest/gtest.h>

#include <vector>

#include "core/sio/baud_timer.h"

namespace {

using psx::BaudTimer;
using psx::Cycles;
using psx::u16;
using psx::u32;

u32 expected(Cycles half, Cycles reload_at, Cycles now) {
  return static_cast<u32>((half - (now - reload_at) % half) & 0x1FFFFF) << 11;
}

TEST(BaudTimer, CountsDownFromTheReloadAtEveryRead) {
  BaudTimer t;
  const u16 baud = 0x88, mul1 = 1, mul64 = 3;  // the pad's rate: a half period of 68 cycles
  t.reload(1000);
  const Cycles reads[] = {1000, 1001, 1067, 1068, 1069, 1300, 1301, 5000, Cycles{1} << 33, (Cycles{1} << 33) + 67};
  for (Cycles now : reads) EXPECT_EQ(t.stat_bits(baud, mul1, now), expected(68, 1000, now)) << now;
  // MUL64: a half period of 0x88 * 64 / 2 = 4352, counted from the same reload.
  for (Cycles now : {Cycles{1} << 33, (Cycles{1} << 33) + 4352, (Cycles{1} << 34) + 5})
    EXPECT_EQ(t.stat_bits(baud, mul64, now), expected(4352, 1000, now)) << now;
  EXPECT_EQ(t.stat_bits(baud, mul1, 1100), expected(68, 1000, 1100));  // earlier again (a state loaded)
  t.reload(2000);
  EXPECT_EQ(t.stat_bits(baud, mul1, 2000), 68u << 11);
  EXPECT_EQ(t.stat_bits(baud, mul1, 2067), 1u << 11);
}

// A state carries the reload time: a timer loaded from it reads what the saved one reads.
TEST(BaudTimer, StateCarriesTheReload) {
  BaudTimer a, b;
  a.reload(12345);
  b.reload(7);
  EXPECT_EQ(b.stat_bits(0x88, 1, 100000), expected(68, 7, 100000));
  psx::StateIO w;
  a.do_state(w);
  w.finish();
  const std::vector<psx::u8> bytes = w.buffer();
  psx::StateIO r(bytes.data(), bytes.size());
  b.do_state(r);
  for (Cycles now : {Cycles{12345}, Cycles{50000}, Cycles{100000}})
    EXPECT_EQ(b.stat_bits(0x88, 1, now), expected(68, 12345, now)) << now;
}

}  // namespace
