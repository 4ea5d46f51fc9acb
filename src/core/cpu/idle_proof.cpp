// The idle-loop proof: symbolic re-execution of a recorded loop iteration (see idle_proof.h),
// mirroring the interpreter's semantics (cpu_execute.h) including the load delay slot.
#include "core/cpu/idle_proof.h"

#include <cstdint>

namespace psx {

namespace {
u32 rs(u32 i) { return (i >> 21) & 31; }
u32 rt(u32 i) { return (i >> 16) & 31; }
u32 rd(u32 i) { return (i >> 11) & 31; }
u32 imm(u32 i) { return i & 0xFFFF; }
u32 simm(u32 i) { return static_cast<u32>(static_cast<s32>(static_cast<s16>(i & 0xFFFF))); }
s64 signed_step(u32 step) { return static_cast<s32>(step); }
}  // namespace

IdleProof::Kind IdleProof::classify(u32 instr) {
  switch (instr >> 26) {
    case 0x00:
      switch (instr & 63) {
        case 0x00: case 0x02: case 0x03: case 0x04: case 0x06: case 0x07:  // shifts
        case 0x21: case 0x23: case 0x24: case 0x25: case 0x26: case 0x27:  // ADDU SUBU AND OR XOR NOR
        case 0x2A: case 0x2B:                                              // SLT SLTU
          return Kind::Alu;
        case 0x08: case 0x09: return Kind::Branch;  // JR, JALR
        default: return Kind::Other;  // traps, syscalls, multiply/divide and HI/LO
      }
    case 0x01: return ((instr >> 16) & 0x1E) == 0x10 ? Kind::Other : Kind::Branch;  // BLTZ/BGEZ, not linking
    case 0x02: case 0x03: case 0x04: case 0x05: case 0x06: case 0x07: return Kind::Branch;
    case 0x09: case 0x0A: case 0x0B: case 0x0C: case 0x0D: case 0x0E: case 0x0F: return Kind::Alu;
    case 0x20: case 0x21: case 0x23: case 0x24: case 0x25: return Kind::Load;  // not LWL/LWR
    case 0x2B: return Kind::Store;  // SW
    default: return Kind::Other;  // narrower and unaligned stores, coprocessors, ADDI (it traps)
  }
}

IdleProof::IdleProof(const std::array<u32, 32>& before, const std::array<u32, 32>& after, u32 load_reg, u32 load_val,
                     const IdleCells& cells)
    : after_(after), cell_line_(cells), load_reg_(load_reg), load_val_(constant(load_val)), start_load_reg_(load_reg),
      start_load_val_(load_val) {
  for (u32 r = 0; r < 32; ++r) {
    steps_[r] = after[r] - before[r];
    regs_[r] = {after[r], steps_[r], true};
  }
  for (u32 c = 0; c < cells.count; ++c) cells_[c] = {cells.after[c], cells.after[c] - cells.before[c], true};
}

void IdleProof::no_wrap(const Val& v, bool sign) {
  const s64 step = signed_step(v.step);
  if (step == 0) return;
  const s64 base = sign ? s64{static_cast<s32>(v.base)} : s64{v.base};
  const s64 lo = sign ? INT32_MIN : 0, hi = sign ? INT32_MAX : s64{UINT32_MAX};
  limit(static_cast<u64>(step > 0 ? (hi - base) / step : (base - lo) / -step));
}

// a < b at k = 0. Without wrapping both sides are linear in k as integers, so their difference
// is too and keeps its sign until it crosses zero.
bool IdleProof::less(const Val& a, const Val& b, bool sign) {
  no_wrap(a, sign);
  no_wrap(b, sign);
  const s64 a0 = sign ? s64{static_cast<s32>(a.base)} : s64{a.base};
  const s64 b0 = sign ? s64{static_cast<s32>(b.base)} : s64{b.base};
  const s64 diff = a0 - b0, slope = signed_step(a.step) - signed_step(b.step);
  if (diff < 0) {
    if (slope > 0) limit(static_cast<u64>((-diff - 1) / slope));
    return true;
  }
  if (slope < 0) limit(static_cast<u64>(diff / -slope));
  return false;
}

// a == b at k = 0: the difference e + k*f (mod 2^32) stays nonzero while, as an integer, it
// stays strictly between 0 and 2^32.
bool IdleProof::equal(const Val& a, const Val& b) {
  const u32 e = a.base - b.base, f = a.step - b.step;
  if (f == 0) return e == 0;
  if (e == 0) {
    limit(0);
    return true;
  }
  const s64 sf = signed_step(f);
  limit(static_cast<u64>(sf > 0 ? (s64{UINT32_MAX} - e) / sf : (s64{e} - 1) / -sf));
  return false;
}

void IdleProof::write(u32 r, const Val& v) {
  regs_[r] = v;
  if (load_reg_ == r) load_reg_ = 0;
}

void IdleProof::delayed_load(u32 r, const Val& v) {
  if (load_reg_ == r) load_reg_ = 0;
  new_reg_ = r;
  new_val_ = v;
}

// v AND mask: a constant when every bit the mask keeps is known.
IdleProof::Val IdleProof::and_mask(const Val& v, u32 mask) {
  if (v.known && v.step == 0 && (mask & ~v.bits) == 0) return constant(v.base & mask);
  if (mask == 0) return constant(0);
  return unknown();
}

IdleProof::Val IdleProof::add(const Val& a, const Val& b) {
  if (!a.affine() || !b.affine()) return unknown();
  return {a.base + b.base, a.step + b.step, true};
}

IdleProof::Val IdleProof::compare(const Val& a, const Val& b, bool sign) {
  if (!a.affine() || !b.affine()) return unknown();
  return constant(less(a, b, sign) ? 1 : 0);
}

bool IdleProof::alu(u32 instr) {
  const Val s = regs_[rs(instr)];
  const u32 i = imm(instr);
  switch (instr >> 26) {
    case 0x00: return special(instr);
    case 0x09: write(rt(instr), add(s, constant(simm(instr)))); break;      // ADDIU
    case 0x0A: write(rt(instr), compare(s, constant(simm(instr)), true)); break;   // SLTI
    case 0x0B: write(rt(instr), compare(s, constant(simm(instr)), false)); break;  // SLTIU
    case 0x0C: write(rt(instr), and_mask(s, i)); break;  // ANDI
    case 0x0D: write(rt(instr), s.constant() ? constant(s.base | i) : i == 0 ? s : unknown()); break;
    case 0x0E: write(rt(instr), s.constant() ? constant(s.base ^ i) : i == 0 ? s : unknown()); break;
    case 0x0F: write(rt(instr), constant(i << 16)); break;  // LUI
    default: return false;
  }
  return true;
}

bool IdleProof::special(u32 instr) {
  const Val s = regs_[rs(instr)], t = regs_[rt(instr)];
  const u32 sh = (instr >> 6) & 31;
  const bool both = s.constant() && t.constant();
  const bool s0 = s.constant() && s.base == 0, t0 = t.constant() && t.base == 0;
  Val r;
  switch (instr & 63) {
    case 0x00: r = t.affine() ? Val{t.base << sh, t.step << sh} : unknown(); break;  // SLL
    case 0x02: r = sh == 0 ? t : t.constant() ? constant(t.base >> sh) : unknown(); break;  // SRL
    case 0x03: r = sh == 0 ? t : t.constant() ? constant(u32(s32(t.base) >> sh)) : unknown(); break;  // SRA
    case 0x04: r = both ? constant(t.base << (s.base & 31)) : unknown(); break;                    // SLLV
    case 0x06: r = both ? constant(t.base >> (s.base & 31)) : unknown(); break;                    // SRLV
    case 0x07: r = both ? constant(u32(s32(t.base) >> (s.base & 31))) : unknown(); break;         // SRAV
    case 0x21: r = add(s, t); break;                                                               // ADDU
    case 0x23: r = add(s, t.affine() ? Val{0u - t.base, 0u - t.step} : unknown()); break;         // SUBU
    case 0x24: r = t.constant() ? and_mask(s, t.base) : s.constant() ? and_mask(t, s.base) : unknown(); break;  // AND
    case 0x25: r = both ? constant(s.base | t.base) : s0 ? t : t0 ? s : unknown(); break;          // OR
    case 0x26: r = both ? constant(s.base ^ t.base) : s0 ? t : t0 ? s : unknown(); break;          // XOR
    case 0x27: r = both ? constant(~(s.base | t.base)) : unknown(); break;                         // NOR
    case 0x2A: r = compare(s, t, true); break;                                                     // SLT
    case 0x2B: r = compare(s, t, false); break;                                                    // SLTU
    default: return false;
  }
  write(rd(instr), r);
  return true;
}

// A branch or jump at path[i]: its outcome must be known and the one recorded (the instruction
// after its delay slot), for every k within the bound.
bool IdleProof::control(const IdleStep* path, u32 n, u32 i) {
  if (i + 2 > n) return false;  // the delay slot belongs to the next iteration: not a plain loop
  const u32 instr = path[i].instr, pc = path[i].pc;
  const Val s = regs_[rs(instr)], t = regs_[rt(instr)];
  const u32 relative = pc + 4 + (simm(instr) << 2);
  const u32 absolute = ((pc + 4) & 0xF0000000) | ((instr & 0x03FFFFFF) << 2);
  const Val zero = constant(0);
  bool taken = true;
  u32 target = relative;
  switch (instr >> 26) {
    case 0x00:  // JR, JALR
      if (!s.constant()) return false;
      target = s.base;
      if ((instr & 63) == 0x09) write(rd(instr), constant(pc + 8));
      break;
    case 0x01:
      if (!s.affine()) return false;
      taken = (rt(instr) & 1) ? !less(s, zero, true) : less(s, zero, true);  // BGEZ : BLTZ
      break;
    case 0x02: target = absolute; break;  // J
    case 0x03:                            // JAL
      target = absolute;
      write(31, constant(pc + 8));
      break;
    case 0x04:
    case 0x05:  // BEQ, BNE
      if (!s.affine() || !t.affine()) return false;
      taken = equal(s, t) == ((instr >> 26) == 0x04);
      break;
    case 0x06:
    case 0x07:  // BLEZ, BGTZ
      if (!s.affine()) return false;
      taken = less(zero, s, true) == ((instr >> 26) == 0x07);
      break;
    default: return false;
  }
  return path[(i + 2) % n].pc == (taken ? target : pc + 8);
}

// A load or store at the address recorded, which must not depend on k. A load of a stored word
// delivers the word's value as the loop left it (base + k*step, like a register); any other load
// what it delivered (memory cannot change before an event but by the loop's stores). A store
// reads rt before the load in flight lands, as the CPU does.
bool IdleProof::memory(const IdleStep& step, bool store) {
  const u32 instr = step.instr;
  const Val addr = add(regs_[rs(instr)], constant(simm(instr)));
  if (!addr.constant() || addr.base != step.addr) return false;
  if (store) {
    if (step.cell == 0) return false;
    cells_[step.cell - 1] = regs_[rt(instr)];
    return true;
  }
  delayed_load(rt(instr), step.cell ? cells_[step.cell - 1] : partial(step.load_value, step.load_bits));
  return true;
}

bool IdleProof::run(const IdleStep* path, u32 n) {
  for (u32 i = 0; i < n; ++i) {
    const u32 instr = path[i].instr;
    new_reg_ = 0;
    new_val_ = constant(0);
    bool ok = false;
    switch (classify(instr)) {
      case Kind::Alu: ok = alu(instr); break;
      case Kind::Load: ok = memory(path[i], false); break;
      case Kind::Store: ok = memory(path[i], true); break;
      case Kind::Branch: ok = control(path, n, i); break;
      case Kind::Other: break;
    }
    if (!ok) return false;
    // As CpuT::step: the previous instruction's load lands, this one's is in flight.
    regs_[load_reg_] = load_val_;
    regs_[0] = constant(0);
    load_reg_ = new_reg_;
    load_val_ = new_val_;
  }
  // The pipeline at the head must be as it was, value included (a save state records it).
  if (load_reg_ != start_load_reg_ || !load_val_.constant() || load_val_.base != start_load_val_) return false;
  for (u32 r = 1; r < 32; ++r) {
    const Val& v = regs_[r];
    if (!v.affine() || v.step != steps_[r] || v.base != after_[r] + steps_[r]) return false;
  }
  for (u32 c = 0; c < cell_line_.count; ++c) {
    const Val& v = cells_[c];
    const u32 step = cell_line_.after[c] - cell_line_.before[c];
    if (!v.affine() || v.step != step || v.base != cell_line_.after[c] + step) return false;
  }
  return true;
}

}  // namespace psx
