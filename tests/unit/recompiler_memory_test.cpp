// The recompiler's native loads, stores, HI/LO moves and BcondZ branches (block_emitter_memory.cpp),
// differentially: every program must end in exactly the state (RAM, scratchpad, devices, CPU
// registers and pipeline, COP0, cycle and instruction counts) it ends in under the interpreter.
// Random streams make accesses through every address kind the native code tells apart: RAM in
// KSEG0, KSEG1 and a KUSEG mirror, the scratchpad, timer registers (I/O, through KUSEG and
// KSEG1, which user mode may not reach), expansion region 1 and wild addresses (bus errors),
// aligned and not (address errors), stores into their own code, with SR switching between
// kernel mode, an isolated cache and user mode, and DCIC data breaks armed or not. Named cases
// pin down the load delay slot and shadow, sign extension, LWL/LWR merging, the HI/LO wait
// after MULT and DIV, and BcondZ links.
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/cpu/cop0.h"
#include "recompiler_test_util.h"
#include "sanitizer_scale.h"

namespace {

using namespace recompiler_test;
using psx::Cop0;

constexpr u32 kBase = 0x80010000;
constexpr u32 kT2 = 10, kT3 = 11, kAt = 1, kRa = 31;
// Base registers, never written by the streams.
constexpr u32 kRamK0 = 23, kScratch = 22, kTimers = 21, kRamK1 = 20, kRamKuseg = 19, kCode = 18, kExp1 = 30;
constexpr u32 kScratchK1 = 27, kKseg2 = 28, kTimersK1 = 24;

std::vector<u32> memory_regs(u32 seed) {
  std::vector<u32> regs = random_regs(seed);
  regs[kRamK0 - 1] = 0x80100000;
  regs[kScratch - 1] = 0x1F800000;
  regs[kTimers - 1] = 0x1F801100;  // timer 0 (psx-spx "Timers"): counter, mode, target
  regs[kRamK1 - 1] = 0xA0100000;
  regs[kRamKuseg - 1] = 0x00300000;  // a mirror of RAM 0x100000 (2 MiB repeats through 8 MiB)
  regs[kCode - 1] = kBase;
  regs[kExp1 - 1] = 0x1F000000;
  regs[kScratchK1 - 1] = 0xBF800000;  // the scratchpad's addresses in KSEG1: a bus error
  regs[kKseg2 - 1] = 0xC0000000;      // KSEG2 (only the cache control register is there)
  regs[kTimersK1 - 1] = 0xBF801100;   // the timers in KSEG1: an address error in user mode
  return regs;
}

// Random words in the data areas the streams read (1 KiB of RAM at 0x80100000, the scratchpad),
// so that loads meet bytes and halfwords of either sign.
std::function<void(Console&)> random_data(u32 seed) {
  return [seed](Console& c) {
    std::mt19937 rng(seed * 7919u);
    for (u32 a = 0; a < 0x400; a += 4) {
      c.write32(0x80100000 + a, u32(rng()));
      c.write32(0x1F800000 + a, u32(rng()));
    }
  };
}

// A base register and an offset for an access of `width` bytes (aligned but one time in eight).
std::pair<u32, u32> random_address(std::mt19937& rng, u32 width, bool store, u32 code_words) {
  const u32 kind = rng() % 18, misalign = rng() % 8 == 0 ? 1 + rng() % 3 : 0;
  const u32 align = ~(width - 1);
  u32 base, off;
  if (kind < 5) base = kRamK0, off = rng() & 0x3FF;
  else if (kind < 8) base = kScratch, off = rng() & 0x3FF;
  else if (kind < 9) base = rng() % 2 ? kTimers : kTimersK1, off = rng() & 0x2F;
  else if (kind < 10) base = kRamK1, off = rng() & 0x3FF;
  else if (kind < 11) base = kRamKuseg, off = rng() & 0x3FF;
  else if (kind < 12) base = kExp1, off = rng() & 0xFF;
  else if (kind < 13) base = kT0 + rng() % 4, off = rng() & 0xFFFF;  // anywhere
  else if (kind < 14 && store) base = kCode, off = (rng() % code_words) * 4;  // into the code
  else if (kind == 16) base = kScratchK1, off = rng() & 0x3FF;
  else if (kind == 17) base = kKseg2, off = rng() & 0x3FF;
  else base = kRamK0, off = rng() & 0x3FF;
  return {base, ((off & align) + misalign) & 0xFFFF};
}

// `length` instructions mixing loads, stores, ALU ops on t0-t3 and r0 (delay-slot uses of the
// loaded registers), MULT/DIV and HI/LO moves, short forward branches (BcondZ with and without
// link), and SR writes (kernel mode, isolated cache, user mode with COP0 usable).
std::vector<u32> memory_stream(u32 seed, u32 length) {
  std::mt19937 rng(seed);
  auto pick = [&](u32 n) { return u32(rng() % n); };
  auto reg = [&]() { return pick(6) == 0 ? 0u : kT0 + pick(4); };
  std::vector<u32> code;
  // Half the time a base register is first copied into at (ADDU), so that the recompiler cannot
  // guess the address (address_guess.h) and compiles the access natively, to make its checks.
  auto via_at = [&](u32 base) {
    if (pick(2)) return base;
    code.push_back(rtype(0x21, base, 0, kAt));
    return kAt;
  };
  while (code.size() < length) {
    const u32 kind = pick(24);
    if (kind < 6) {  // LB LH LWL LW LBU LHU LWR
      const u32 op = 0x20 + pick(7);
      const u32 width = op == 0x23 ? 4 : op == 0x21 || op == 0x25 ? 2 : 1;
      const auto [b, off] = random_address(rng, width, false, length);
      code.push_back(itype(op, via_at(b), reg(), off));
    } else if (kind < 9) {  // SB SH SW, SWL SWR now and then
      static constexpr u32 kStores[] = {0x28, 0x29, 0x2B, 0x2B, 0x28, 0x29, 0x2B, 0x2A, 0x2E};
      const u32 op = kStores[pick(9)];
      const u32 width = op == 0x2B ? 4 : op == 0x29 ? 2 : 1;
      const auto [b, off] = random_address(rng, width, true, length);
      code.push_back(itype(op, via_at(b), reg(), off));
    } else if (kind < 14) {
      static constexpr u32 kFuncts[] = {0x00, 0x02, 0x03, 0x04, 0x21, 0x23, 0x24, 0x25, 0x26, 0x2A, 0x2B};
      code.push_back(rtype(kFuncts[pick(11)], reg(), reg(), reg(), pick(32)));
    } else if (kind < 15) {
      code.push_back(rtype(0x18 + pick(4), reg(), reg(), 0));  // MULT MULTU DIV DIVU
    } else if (kind < 17) {
      code.push_back(rtype(0x10 + pick(4), reg(), 0, reg()));  // MFHI MTHI MFLO MTLO
    } else if (kind < 19) {  // BLTZ BGEZ BLTZAL BGEZAL, and rt values the CPU decodes as those
      static constexpr u32 kRt[] = {0x00, 0x01, 0x10, 0x11, 0x02, 0x13};
      code.push_back(itype(0x01, pick(4) == 0 ? kRa : reg(), kRt[pick(6)], 1 + pick(4)));
    } else if (kind < 20) {
      code.push_back(itype(0x04 + pick(2), reg(), reg(), 1 + pick(4)));  // BEQ BNE
    } else if (kind < 21) {  // SR = 0, IsC, or KUc with CU0 (so that MTC0 still works)
      const u32 v = pick(8);
      code.push_back(itype(0x0F, 0, kAt, v < 4 ? 0 : v < 7 ? 1 : 0x1000));   // lui at
      code.push_back(itype(0x0D, kAt, kAt, v < 7 ? 0 : 2));                  // ori at
      code.push_back(itype(0x10, 4, kAt, 0) | 12 << 11);                     // mtc0 at, sr
    } else {
      code.push_back(itype(0x09, reg(), reg(), rng() & 0xFFFF));  // ADDIU
    }
  }
  code.resize(length);
  code.push_back(itype(0x10, 4, 0, 0) | 12 << 11);  // mtc0 zero, sr: kernel mode, cache on
  code.push_back(j(kBase));
  code.push_back(kNop);
  return code;
}

TEST(RecompilerMemory, RandomMemoryStreams) {
  // 600 instructions fit the i-cache with the handler, so the blocks run their native code.
  for (int seed = 1; seed <= test_scale::sized(24, 6); ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_code(memory_stream(seed, 600), kBase, 0, memory_regs(seed), 2, random_data(seed));
  }
}

// DCIC data breaks (psx-spx "COP0 - Debug Registers") on reads and writes of a 64-byte range of
// the data area, first with DCIC bit 31 clear (not armed: the streams run as without DCIC), then
// armed (a Bp exception after the access, at the debug vector 0x80000040, whose nops run into the
// handler at 0x80000080).
TEST(RecompilerMemory, StreamsWithDataBreaks) {
  for (u32 trap : {0u, 1u}) {
    for (int seed = 31; seed < 31 + test_scale::sized(4, 2); ++seed) {
      SCOPED_TRACE("seed " + std::to_string(seed) + (trap ? " trap" : ""));
      const u32 dcic = Cop0::kDcicDE | Cop0::kDcicDAE | Cop0::kDcicDR | Cop0::kDcicDW | Cop0::kDcicME |
                       (trap ? Cop0::kDcicTR : 0);
      // The break watches 64 bytes of the streams' RAM data, or (odd seeds) the timers' registers
      // in KUSEG, which the streams' stores reach through their calls.
      const u32 bda = seed % 2 ? 0x1F801100 : 0x80100040;
      std::vector<u32> code = {
          itype(0x0F, 0, kAt, bda >> 16), itype(0x0D, kAt, kAt, bda & 0xFFFF), itype(0x10, 4, kAt, 0) | 5 << 11,  // BDA
          itype(0x0F, 0, kAt, 0xFFFF), itype(0x0D, kAt, kAt, 0xFFC0), itype(0x10, 4, kAt, 0) | 9 << 11,  // BDAM
          itype(0x0F, 0, kAt, dcic >> 16), itype(0x0D, kAt, kAt, dcic & 0xFFFF),
          itype(0x10, 4, kAt, 0) | 7 << 11};  // DCIC
      const std::vector<u32> body = memory_stream(seed, 500);
      code.insert(code.end(), body.begin(), body.end());
      code.back() = kNop;  // the loop goes back past the setup
      code[code.size() - 2] = j(kBase + 9 * 4);
      expect_same_code(code, kBase, 0, memory_regs(seed), 2, random_data(seed));
    }
  }
}

// Load and store cases next to each other, each named, in one loop; after each, t0-t3 are added
// into s0 so that every value reaches the state (added, not xored: the loop runs each case many
// times, and an even number of xors of a wrong value would cancel).
TEST(RecompilerMemory, NamedLoadStoreCases) {
  const auto mem = [](u32 op, u32 base, u32 rt, u32 off) { return itype(op, base, rt, off); };
  const auto addu = [](u32 d, u32 s, u32 t) { return rtype(0x21, s, t, d); };
  constexpr u32 kSeg1 = 29, kSeg3 = 3;  // RAM's offset 100000h in KUSEG's second and fourth 512 MiB
  constexpr u32 kLb = 0x20, kLh = 0x21, kLw = 0x23, kLbu = 0x24, kLhu = 0x25, kSb = 0x28, kSh = 0x29, kSw = 0x2B;
  const std::vector<std::vector<u32>> cases = {
      {mem(kLw, kRamK0, kT0, 0), addu(kT1, kT0, kT0)},              // delay slot reads the old t0
      {mem(kLw, kRamK0, kT0, 4), kNop, addu(kT1, kT0, kT0)},        // read in the shadow: a stall
      {mem(kLw, kRamK0, kT0, 8), mem(kLw, kRamK0, kT0, 12), addu(kT1, kT0, 0)},  // same register twice
      {mem(kLw, kRamK0, kT0, 16), mem(kLw, kRamK0, kT1, 20), mem(kLw, kRamK0, kT2, 24), kNop},
      {mem(kSw, kRamK0, kRamK1, 0x100), mem(kLb, kRamK0, kT0, 0x103), mem(kLbu, kRamK0, kT1, 0x103),
       mem(kLh, kRamK0, kT2, 0x102), mem(kLhu, kRamK0, kT3, 0x102), kNop},  // sign and zero extension of A010h
      {mem(kLw, kScratch, kT0, 0), addu(kT1, kT0, 0), kNop},        // scratchpad: no shadow
      {mem(kLw, kRamK0, kT0, 28), mem(kLw, kScratch, kT1, 4), kNop},  // scratchpad waits for RAM
      {mem(kLw, kRamK1, kT0, 32), mem(kLw, kRamKuseg, kT1, 32), kNop},  // mirrors of RAM 0x100020
      {mem(kSw, kRamK0, kT2, 36), mem(kLw, kRamK0, kT0, 36), kNop},  // a store, read back
      {mem(kSb, kRamK0, kT2, 41), mem(kSh, kRamK0, kT2, 42), mem(kLw, kRamK0, kT0, 40), kNop},
      {mem(kSw, kScratch, kT3, 8), mem(kLw, kScratch, kT1, 8), kNop},
      {mem(kLw, kRamK0, kT0, 2), kNop},                              // address error (AdEL)
      {mem(kSh, kRamK0, kT0, 3), kNop},                              // address error (AdES)
      {mem(kLw, kTimers, kT0, 0), mem(kSw, kTimers, kT2, 8), kNop},  // I/O: call steps
      // The same addresses through a copy of the base, which the recompiler cannot guess, so
      // that the native code checks them and takes the calls: I/O, the scratchpad's addresses
      // in KSEG1 and KSEG2 (bus errors).
      {addu(kAt, kTimers, 0), mem(kLw, kAt, kT0, 0), mem(kSw, kAt, kT2, 8), kNop},
      {addu(kAt, kScratchK1, 0), mem(kLw, kAt, kT0, 0), kNop, mem(kSw, kAt, kT2, 8), kNop},
      {addu(kAt, kKseg2, 0), mem(kLw, kAt, kT0, 0), kNop, mem(kSw, kAt, kT2, 8), kNop},
      // RAM's offsets in KUSEG's second and fourth 512 MiB, which no mirror maps (Bus::physical
      // keeps all of a KUSEG address): bus errors, not RAM.
      {addu(kAt, kSeg1, 0), mem(kLw, kAt, kT0, 0x20), kNop, mem(kSw, kAt, kT2, 0x24), kNop},
      {addu(kAt, kSeg3, 0), mem(kLw, kAt, kT0, 0x20), kNop, mem(kSw, kAt, kT2, 0x24), kNop},
      {mem(kLw, kRamK0, kT0, 44), mem(kSw, kRamK0, kT0, 48), kNop},  // the delay slot stores the old t0
      {mem(kLw, kRamK0, kT0, 52), mem(kLw, kT0, kT1, 0), kNop},      // base read in the delay slot
  };
  constexpr u32 kS0 = 16;
  std::vector<u32> code;
  for (const auto& c : cases) {
    code.insert(code.end(), c.begin(), c.end());
    for (u32 r : {kT0, kT1, kT2, kT3}) code.push_back(rtype(0x21, kS0, r, kS0));  // addu s0, s0, r
  }
  code.insert(code.end(), {itype(0x09, kT2, kT2, 0x0123), mem(kSw, kRamK0, kS0, 60),
                           j(kBase), itype(0x09, kS1, kS1, 1)});
  std::vector<u32> regs = memory_regs(7);
  regs[kT2 - 1] = 0x80818283;
  regs[kT3 - 1] = 0xFEDCBA98;
  regs[kSeg1 - 1] = 0x20100000;
  regs[kSeg3 - 1] = 0x60100000;
  expect_same_code(code, kBase, 0, regs, 3);
  // The same with SR.IsC set: every store stays out of memory.
  expect_same_code(code, kBase, Cop0::kIsC, regs, 3);
}

// LWL/LWR pairs (psx-spx "CPU Load/Store Opcodes") at all four alignments in RAM and the
// scratchpad: the usual pair, whose second load merges with the first's value still in its delay
// slot; either alone after a load to the same register (merging with that load's value) or to
// another register, or after the load has landed; into r0; and SWL/SWR pairs, read back.
TEST(RecompilerMemory, UnalignedLoadsAndStores) {
  constexpr u32 kLw = 0x23, kLwl = 0x22, kLwr = 0x26, kSwl = 0x2A, kSwr = 0x2E;
  const auto mem = [](u32 op, u32 base, u32 rt, u32 off) { return itype(op, base, rt, off); };
  std::vector<u32> code;
  for (u32 base : {kRamK0, kScratch}) {
    for (u32 a = 0; a < 4; ++a) {
      const u32 at = 0x80 + 8 * a + a;  // a word-pair's first byte plus the alignment
      const std::vector<std::vector<u32>> cases = {
          {mem(kLwr, base, kT0, at), mem(kLwl, base, kT0, at + 3), kNop},
          {mem(kLwl, base, kT1, at + 3), mem(kLwr, base, kT1, at), kNop},
          {mem(kLw, base, kT2, 0x40), mem(kLwl, base, kT2, at), kNop},       // merges with the LW's value
          {mem(kLw, base, kT3, 0x44), mem(kLwr, base, kT3, at), kNop},
          {mem(kLw, base, kT2, 0x48), kNop, mem(kLwl, base, kT2, at), kNop},  // the LW has landed
          {mem(kLw, base, kT1, 0x4C), mem(kLwr, base, kT0, at), kNop},       // another register
          {mem(kLwl, base, 0, at), mem(kLwr, base, 0, at), kNop},           // r0
          {mem(kSwl, base, kT0, 0x100 + at), mem(kSwr, base, kT1, 0x104 + at),
           mem(kLw, base, kT2, 0x100 + 8 * a), mem(kLw, base, kT3, 0x104 + 8 * a), kNop},
      };
      for (const auto& c : cases) {
        code.insert(code.end(), c.begin(), c.end());
        for (u32 r : {kT0, kT1, kT2, kT3}) code.push_back(rtype(0x21, 16, r, 16));  // addu s0, s0, r
      }
    }
  }
  code.insert(code.end(), {mem(0x2B, kRamK0, 16, 0x3F0), j(kBase), itype(0x09, kS1, kS1, 1)});
  expect_same_code(code, kBase, 0, memory_regs(13), 3, random_data(13));
}

// MFHI/MFLO right after MULT, MULTU, DIV, DIVU (time waits for the result) and a few
// instructions later, MTHI/MTLO, and BcondZ: BLTZAL/BGEZAL links taken and not, a link read in
// the delay slot, ra as the tested register (read before the link is written), and a backward
// BGEZ loop (its loop head).
TEST(RecompilerMemory, HiLoAndBcondZ) {
  const auto r = [](u32 funct, u32 s, u32 t, u32 d) { return rtype(funct, s, t, d); };
  const auto bcondz = [](u32 rt, u32 s, u32 off) { return itype(0x01, s, rt, off); };
  const auto addiu = [](u32 t, u32 s, u32 imm) { return itype(0x09, s, t, imm); };
  std::vector<u32> code = {
      r(0x18, kT0, kT1, 0), r(0x10, 0, 0, kT2),           // mult; mfhi at once
      r(0x19, kT1, kT0, 0), kNop, kNop, r(0x12, 0, 0, kT3),  // multu; mflo later
      r(0x1A, kT0, kT1, 0), r(0x12, 0, 0, kT2),           // div; mflo at once (36 cycles)
      r(0x1B, kT3, kT1, 0), r(0x10, 0, 0, kT3),           // divu; mfhi
      r(0x11, kT2, 0, 0), r(0x13, kT3, 0, 0), r(0x10, 0, 0, kT0), r(0x12, 0, 0, kT1),  // mthi; mtlo; mfhi; mflo
      addiu(kT2, 0, 3),                                   // loop: t2 = 3
      addiu(kT2, kT2, 0xFFFF),                            // t2 -= 1
      bcondz(0x01, kT2, 0xFFFE),                          // bgez t2, back one (loop head)
      addiu(kT3, kT3, 1),                                 // delay slot
      bcondz(0x10, kT2, 2),                               // bltzal t2 (taken: t2 = -1)
      r(0x21, kRa, 0, kT0),                               // delay slot reads the link
      kNop,
      bcondz(0x11, kT2, 2),                               // bgezal t2 (not taken; links anyway)
      r(0x21, kRa, kT0, kT1),                             // delay slot
      bcondz(0x11, kRa, 2),                               // bgezal ra: tests the old ra
      kNop, kNop,
      r(0x18, kRa, kT1, 0), r(0x12, 0, 0, kT3),           // mult by the link; mflo
      j(kBase), addiu(kS1, kS1, 1)};
  std::vector<u32> regs = memory_regs(11);
  regs[kT0 - 1] = 0x7FFFFFFF;
  regs[kT1 - 1] = 0xFFFFFFFD;
  expect_same_code(code, kBase, 0, regs, 3);
}

// Cached code that rewrites a word of its own block with a native SW, then evicts that word's
// i-cache line (a call to code 4 KiB away, which maps to the same line) so that the next pass
// fetches the new word: the interpreter runs it, and so must the recompiler, whose store has
// dropped the block compiled from the old word (CodePages).
TEST(RecompilerMemory, SelfModifyingCachedCode) {
  const u32 patched = kBase + 0x20, evict = patched + 0x1000;
  std::vector<u32> code = {
      itype(0x23, kCode, kT0, 0x20),                  // 0: lw t0, 0x20(code): the word at 8
      kNop,
      itype(0x09, kT0, kT0, 1),                       // 2: its immediate + 1
      itype(0x2B, kCode, kT0, 0x20),                  // 3: sw t0, 0x20(code)
      0x03u << 26 | ((evict >> 2) & 0x03FFFFFF),      // 4: jal evict
      kNop,
      kNop, kNop,
      itype(0x09, kS1, kS1, 1),                       // 8: addiu s1, s1, 1 (patched each pass)
      j(kBase), kNop};
  const std::vector<u32> evictor = {rtype(0x08, kRa, 0, 0), kNop};  // jr ra
  std::vector<psx::u8> states[2];
  for (int rec = 0; rec < 2; ++rec) {
    Console c;
    if (rec) c.set_cpu_mode(Console::CpuMode::Recompiler);
    load_code(c, code, kBase, 0, memory_regs(3));
    for (u32 i = 0; i < evictor.size(); ++i) c.write32(evict + 4 * i, evictor[i]);
    c.run_frames(2);
    states[rec] = state_of(c);
    if (rec) {
      EXPECT_GT(c.recompiler_stats().invalidated, 0u) << "the native store dropped no block";
    }
    EXPECT_GT(c.cpu().reg(kS1), 1000u);  // the loop ran (and s1 grew by ever larger steps)
  }
  EXPECT_TRUE(states[0] == states[1]) << "state differs under the recompiler";
}

}  // namespace

namespace {

// A store that stops the CPU (the debug port's exit request, 1F802082h, on the loop's 100th
// pass; before that the store goes to 1F802092h, which ignores it), through a base the
// recompiler cannot guess, so compiled natively and then taken as a call: nothing after it may
// run, so the native segment must not go on (the guard is checked again after the call).
TEST(RecompilerMemory, StoreThatStopsTheCpu) {
  const std::vector<u32> code = {
      itype(0x09, kT1, kT1, 1),             // addiu t1, t1, 1
      itype(0x0B, kT1, kT3, 100),           // sltiu t3, t1, 100
      rtype(0x00, 0, kT3, kT3, 4),          // sll t3, t3, 4
      rtype(0x21, kTimers, kT3, kAt),       // addu at, s5, t3 (timers, 1F801100h, + 0 or 16)
      itype(0x0D, 0, kT0, 7),               // ori t0, zero, 7
      itype(0x29, kAt, kT0, 0x0F82),        // sh t0, F82h(at): exit request with code 7
      itype(0x09, kT2, kT2, 1),             // addiu t2, t2, 1: must not run after the request
      j(kBase), kNop};
  std::vector<u32> regs = memory_regs(5);
  regs[kT1 - 1] = 0;
  regs[kT2 - 1] = 0;
  expect_same_code(code, kBase, 0, regs, 1);
}

// A block compiled from a stale i-cache line: the code at P is run (cached), rewritten in RAM
// (the store drops P's block), run again from the cache's old words (compiled anew from them),
// then evicted by code 4 KiB away. From then on the loop calls P: the first call misses and
// fills the new word from RAM, and every later one hits a line whose tag matches P but whose
// words are not the ones compiled, so the guard must refuse the block (the interpreter runs the
// new word, adding 2 to s1 where the old one added 1). P sits at each word of its line, so the
// line check compares three, three, two or one of its words (P and the jr and nop after it).
TEST(RecompilerMemory, BlockCompiledFromAStaleLineRefusedAfterARefill) {
  for (u32 at = 0; at < 4; ++at) {
    SCOPED_TRACE("P at word " + std::to_string(at) + " of its line");
    const u32 p = kBase + 0x40 + 4 * at, evict = p + 0x1000;
    std::vector<u32> code = {
        jal(p),                                        // 0: P cached with the old word
        kNop,
        itype(0x23, kCode, kT0, 0x40 + 4 * at),        // 2: lw t0, P
        kNop,
        itype(0x09, kT0, kT0, 1),                      // 4: addiu s1, s1, 1 -> addiu s1, s1, 2
        itype(0x2B, kCode, kT0, 0x40 + 4 * at),        // 5: sw t0, P (RAM only)
        jal(p),                                        // 6: the cache's old word
        kNop,
        jal(evict),                                    // 8: jal evict
        kNop,
        jal(p),                                        // 10: the loop
        kNop,
        j(kBase + 10 * 4), kNop};
    code.resize(16 + at, kNop);
    for (u32 w : {itype(0x09, kS1, kS1, 1), rtype(0x08, kRa, 0, 0), kNop}) code.push_back(w);  // P
    const std::vector<u32> evictor = {rtype(0x08, kRa, 0, 0), kNop};  // jr ra
    std::vector<u32> regs = memory_regs(5);
    regs[kS1 - 1] = 0;
    std::vector<psx::u8> states[2];
    for (int rec = 0; rec < 2; ++rec) {
      Console c;
      if (rec) c.set_cpu_mode(Console::CpuMode::Recompiler);
      load_code(c, code, kBase, 0, regs);
      for (u32 i = 0; i < evictor.size(); ++i) c.write32(evict + 4 * i, evictor[i]);
      c.run_frames(2);
      states[rec] = state_of(c);
      EXPECT_GT(c.cpu().reg(kS1), 2000u);  // the loop ran
    }
    EXPECT_TRUE(states[0] == states[1]) << "state differs under the recompiler";
  }
}

}  // namespace
