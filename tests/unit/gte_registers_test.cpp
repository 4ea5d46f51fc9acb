// GTE register quirks with expected values worked by hand from psx-spx "GTE Data Register
// Summary" / "GTE Control Register Summary": sign extension, IRGB/ORGB, LZCS/LZCR, the SXY
// FIFO, FLAG bit 31, and a save-state round trip.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/gte/gte.h"

namespace psx {
namespace {

constexpr u32 kLzcs = 30, kLzcr = 31, kIrgb = 28, kOrgb = 29, kFlag = 63;

TEST(GteRegisters, SixteenBitRegistersSignOrZeroExtend) {
  Gte g;
  g.write_data(1, 0x12348000);  // VZ0: s16, the upper half is dropped and reads as sign
  EXPECT_EQ(g.read_data(1), 0xFFFF8000u);
  g.write_data(9, 0x00017FFF);  // IR1: s16
  EXPECT_EQ(g.read_data(9), 0x00007FFFu);
  g.write_data(7, 0xFFFF8000);  // OTZ: u16
  EXPECT_EQ(g.read_data(7), 0x00008000u);
  g.write_data(17, 0xABCDFFFF);  // SZ1: u16
  EXPECT_EQ(g.read_data(17), 0x0000FFFFu);
  g.write_control(26, 0x00008000);  // H: stored unsigned, but reads sign-extended
  EXPECT_EQ(g.read_control(26), 0xFFFF8000u);
  g.write_control(4, 0x5555AAAA);  // RT33 alone in its word: the high half reads as its sign
  EXPECT_EQ(g.read_control(4), 0xFFFFAAAAu);
  g.write_control(0, 0x5555AAAA);  // RT11/RT12: both halves kept
  EXPECT_EQ(g.read_control(0), 0x5555AAAAu);
}

TEST(GteRegisters, LzcrCountsLeadingSignBits) {
  Gte g;
  const struct {
    u32 lzcs, lzcr;
  } cases[] = {
      {0x00000000, 32},  // all 32 bits equal the (clear) sign bit
      {0xFFFFFFFF, 32},  // negative: leading ones are counted
      {0x00001000, 19},  // bit 12 is the first one: 31-12 = 19
      {0x80000000, 1},
      {0x7FFFFFFF, 1},
      {0xFFFF0000, 16},
  };
  for (const auto& c : cases) {
    g.write_data(kLzcs, c.lzcs);
    EXPECT_EQ(g.read_data(kLzcs), c.lzcs);
    EXPECT_EQ(g.read_data(kLzcr), c.lzcr) << "LZCS=" << std::hex << c.lzcs;
  }
  g.write_data(kLzcr, 5);  // read-only
  EXPECT_EQ(g.read_data(kLzcr), 16u);
}

TEST(GteRegisters, IrgbExpandsAndOrgbSaturates) {
  Gte g;
  g.write_data(kIrgb, 0x0000FC21);  // R=01h, G=01h, B=1Fh (bit 15 ignored)
  EXPECT_EQ(g.read_data(9), 0x80u);    // 1 * 80h
  EXPECT_EQ(g.read_data(10), 0x80u);
  EXPECT_EQ(g.read_data(11), 0xF80u);  // 1Fh * 80h
  EXPECT_EQ(g.read_data(kOrgb), 0x7C21u);
  EXPECT_EQ(g.read_data(kIrgb), 0x7C21u);  // IRGB reads as ORGB
  g.write_data(9, 0xFFFF);  // IR1 = -1: saturates to 0
  g.write_data(10, 0x7FFF);  // IR2 = 7FFFh / 80h = FFh: saturates to 1Fh
  g.write_data(11, 0x0100);  // IR3 = 100h / 80h = 2
  EXPECT_EQ(g.read_data(kOrgb), (2u << 10) | (0x1Fu << 5));
  g.write_data(kOrgb, 0);  // read-only
  EXPECT_EQ(g.read_data(kOrgb), (2u << 10) | (0x1Fu << 5));
}

TEST(GteRegisters, SxypPushesFifoAndReadsSxy2) {
  Gte g;
  g.write_data(12, 0x11111111);
  g.write_data(13, 0x22222222);
  g.write_data(14, 0x33333333);
  g.write_data(15, 0x44444444);  // SXY0 <- SXY1 <- SXY2 <- value
  EXPECT_EQ(g.read_data(12), 0x22222222u);
  EXPECT_EQ(g.read_data(13), 0x33333333u);
  EXPECT_EQ(g.read_data(14), 0x44444444u);
  EXPECT_EQ(g.read_data(15), 0x44444444u);
}

TEST(GteRegisters, FlagBit31IsOrOfErrorBits) {
  Gte g;
  const struct {
    u32 written, read;
  } cases[] = {
      {0x00001000, 0x00001000},  // IR0 saturation (bit 12) is not an error bit
      {0x00400000, 0x00400000},  // IR3 (bit 22) neither
      {0x00380000, 0x00380000},  // colour FIFO R/G/B (bits 21-19) neither
      {0x00800000, 0x80800000},  // IR2 (bit 23) is
      {0x00002000, 0x80002000},  // SY2 (bit 13) is
      {0x00020000, 0x80020000},  // divide overflow (bit 17) is
      {0x40000000, 0xC0000000},  // MAC1 positive overflow (bit 30) is
      {0x00000FFF, 0x00000000},  // bits 0-11 always read 0
      {0x80000000, 0x00000000},  // bit 31 cannot be written
  };
  for (const auto& c : cases) {
    g.write_register(kFlag, c.written);
    EXPECT_EQ(g.read_register(kFlag), c.read) << "written " << std::hex << c.written;
  }
}

// Gte::data_field() (the recompiler's native GTE moves) must name, for every data register that
// is a plain field, the bytes read_data()/write_data() use: all but IRGB (28) and ORGB (29) read
// as one field; writes to SXYP (15, a FIFO push), LZCS (30, sets LZCR) and LZCR (31, read-only)
// are more than one. A write through the field's bytes must leave every register as write_data()
// does, and read_data() must give the field's bytes, sign- or zero-extended as the field says.
TEST(GteRegisters, PlainDataFieldsMoveAsReadAndWriteDo) {
  for (u32 r = 0; r < 32; ++r) {
    SCOPED_TRACE("register " + std::to_string(r));
    const bool special = r == 28 || r == 29, written = !special && r != 15 && r != 30 && r != 31;
    const auto read = Gte::data_field(r, false), write = Gte::data_field(r, true);
    ASSERT_EQ(read.has_value(), !special);
    ASSERT_EQ(write.has_value(), written);
    Gte by_function, by_field;
    for (u32 k = 0; k < 64; ++k) {  // the same distinct values everywhere first
      by_function.write_register(k, 0x9E3779B9u * (k + 1));
      by_field.write_register(k, 0x9E3779B9u * (k + 1));
    }
    const u32 v = 0xC0DE8ABCu + r;
    if (write) {
      by_function.write_data(r, v);
      std::memcpy(reinterpret_cast<u8*>(&by_field) + write->offset, &v, write->bytes);
      for (u32 k = 0; k < 64; ++k) EXPECT_EQ(by_field.read_register(k), by_function.read_register(k)) << k;
    }
    if (read) {
      u32 raw = 0;
      std::memcpy(&raw, reinterpret_cast<const u8*>(&by_function) + read->offset, read->bytes);
      if (read->bytes == 2) raw = read->sign ? u32(s32(s16(raw))) : (raw & 0xFFFF);
      EXPECT_EQ(raw, by_function.read_data(r));
    }
  }
}

TEST(GteRegisters, SaveStateRoundTripKeepsAllRegisters) {
  Gte a;
  for (u32 r = 0; r < 64; ++r) a.write_register(r, 0x9E3779B9u * (r + 1));
  StateIO out;
  a.do_state(out);
  Gte b;
  StateIO in(out.buffer().data(), out.buffer().size());
  b.do_state(in);
  EXPECT_TRUE(in.at_end());
  for (u32 r = 0; r < 64; ++r) EXPECT_EQ(b.read_register(r), a.read_register(r)) << "register " << r;
}

}  // namespace
}  // namespace psx
