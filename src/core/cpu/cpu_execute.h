// R3000A instruction decode and execution: primary opcodes, SPECIAL, BcondZ, COP0 and COP2.
#pragma once

namespace psx {

template <class BusT>
void CpuT<BusT>::execute(u32 instr) {
  using namespace cpu_detail;
  const u32 s = regs_[rs(instr)];
  const u32 t = regs_[rt(instr)];
  switch (op(instr)) {
    case 0x00: execute_special(instr); break;
    case 0x01: execute_bcondz(instr); break;
    case 0x02: loop_branch((pc_ & 0xF0000000) | ((instr & 0x03FFFFFF) << 2), true); break;  // J
    case 0x03:                                                                          // JAL
      write_reg(31, next_pc_);
      branch((pc_ & 0xF0000000) | ((instr & 0x03FFFFFF) << 2), true);
      break;
    case 0x04: loop_branch(pc_ + (simm(instr) << 2), s == t); break;         // BEQ
    case 0x05: loop_branch(pc_ + (simm(instr) << 2), s != t); break;         // BNE
    case 0x06: loop_branch(pc_ + (simm(instr) << 2), s32(s) <= 0); break;    // BLEZ
    case 0x07: loop_branch(pc_ + (simm(instr) << 2), s32(s) > 0); break;     // BGTZ
    case 0x08: {                                                        // ADDI
      u32 r = s + simm(instr);
      if (((s ^ r) & (simm(instr) ^ r)) >> 31) exception(Exception::Overflow);
      else write_reg(rt(instr), r);
      break;
    }
    case 0x09: write_reg(rt(instr), s + simm(instr)); break;             // ADDIU
    case 0x0A: write_reg(rt(instr), s32(s) < s32(simm(instr))); break;   // SLTI
    case 0x0B: write_reg(rt(instr), s < simm(instr)); break;             // SLTIU
    case 0x0C: write_reg(rt(instr), s & imm(instr)); break;              // ANDI
    case 0x0D: write_reg(rt(instr), s | imm(instr)); break;              // ORI
    case 0x0E: write_reg(rt(instr), s ^ imm(instr)); break;              // XORI
    case 0x0F: write_reg(rt(instr), imm(instr) << 16); break;            // LUI
    case 0x10: execute_cop0(instr); break;
    case 0x12: execute_cop2(instr); break;
    case 0x11:
    case 0x13: execute_absent_cop(instr); break;  // COP1, COP3
    case 0x20: load(instr, 1, true); break;            // LB
    case 0x21: load(instr, 2, true); break;            // LH
    case 0x22: load_unaligned(instr, true); break;     // LWL
    case 0x23: load(instr, 4, false); break;           // LW
    case 0x24: load(instr, 1, false); break;           // LBU
    case 0x25: load(instr, 2, false); break;           // LHU
    case 0x26: load_unaligned(instr, false); break;    // LWR
    case 0x28: store(instr, 1); break;                 // SB
    case 0x29: store(instr, 2); break;                 // SH
    case 0x2A: store_unaligned(instr, true); break;    // SWL
    case 0x2B: store(instr, 4); break;                 // SW
    case 0x2E: store_unaligned(instr, false); break;   // SWR
    case 0x32: {                                        // LWC2
      if (!(cop0_.sr & Cop0::kCU2)) {
        exception(Exception::CopUnusable, 2);
        break;
      }
      u32 addr = s + simm(instr), v;
      if (!check_address(addr, 3, Exception::AddressLoad)) break;
      if constexpr (kLoadShadow) wait_load();  // the GTE load is not shadowed, but waits its turn
      if (!bus_.read32(addr, v)) {
        exception(Exception::BusData);
        break;
      }
      wait_gte();
      gte_.write_data(rt(instr), v);
      if ((cop0_.dcic & Cop0::kDcicDAE) && data_break(addr, 4, false)) take_data_break();
      break;
    }
    case 0x3A: {  // SWC2
      if (!(cop0_.sr & Cop0::kCU2)) {
        exception(Exception::CopUnusable, 2);
        break;
      }
      u32 addr = s + simm(instr);
      if (!check_address(addr, 3, Exception::AddressStore)) break;
      wait_gte();
      if (cop0_.sr & Cop0::kIsC) bus_.isolated_store(addr, gte_.read_data(rt(instr)));
      else if (!bus_.write32(addr, gte_.read_data(rt(instr)))) {
        exception(Exception::BusData);
        break;
      }
      if ((cop0_.dcic & Cop0::kDcicDAE) && data_break(addr, 4, true)) take_data_break();
      break;
    }
    case 0x30:
    case 0x31:
    case 0x33:
    case 0x38:
    case 0x39:
    case 0x3B: execute_absent_cop(instr); break;  // LWC0/1/3, SWC0/1/3
    default: exception(Exception::Reserved); break;
  }
}

template <class BusT>
void CpuT<BusT>::execute_special(u32 instr) {
  using namespace cpu_detail;
  const u32 s = regs_[rs(instr)];
  const u32 t = regs_[rt(instr)];
  const u32 d = rd(instr);
  switch (funct(instr)) {
    case 0x00: write_reg(d, t << shamt(instr)); break;                  // SLL
    case 0x02: write_reg(d, t >> shamt(instr)); break;                  // SRL
    case 0x03: write_reg(d, u32(s32(t) >> shamt(instr))); break;        // SRA
    case 0x04: write_reg(d, t << (s & 31)); break;                      // SLLV
    case 0x06: write_reg(d, t >> (s & 31)); break;                      // SRLV
    case 0x07: write_reg(d, u32(s32(t) >> (s & 31))); break;            // SRAV
    case 0x08: branch(s, true); break;                                  // JR
    case 0x09:                                                          // JALR
      write_reg(d, next_pc_);
      branch(s, true);
      break;
    case 0x0C: exception(Exception::Syscall); break;
    case 0x0D: exception(Exception::Break); break;
    case 0x10: wait_muldiv(); write_reg(d, hi_); break;                 // MFHI
    case 0x11: hi_ = s; break;                                          // MTHI
    case 0x12: wait_muldiv(); write_reg(d, lo_); break;                 // MFLO
    case 0x13: lo_ = s; break;                                          // MTLO
    case 0x18: {                                                        // MULT
      u64 r = u64(s64(s32(s)) * s64(s32(t)));
      hi_ = u32(r >> 32);
      lo_ = u32(r);
      // Early-out multiplier: its time goes by the magnitude of rs.
      u32 m = s32(s) < 0 ? ~s : s;
      muldiv_ready_at_ = sched_.now() + multiply_cycles(m);
      break;
    }
    case 0x19: {  // MULTU
      u64 r = u64(s) * u64(t);
      hi_ = u32(r >> 32);
      lo_ = u32(r);
      muldiv_ready_at_ = sched_.now() + multiply_cycles(s);
      break;
    }
    case 0x1A:  // DIV: division by zero and 0x80000000/-1 give the documented results
      if (t == 0) {
        hi_ = s;
        lo_ = s32(s) >= 0 ? 0xFFFFFFFF : 1;
      } else if (s == 0x80000000 && t == 0xFFFFFFFF) {
        hi_ = 0;
        lo_ = 0x80000000;
      } else {
        hi_ = u32(s32(s) % s32(t));
        lo_ = u32(s32(s) / s32(t));
      }
      muldiv_ready_at_ = sched_.now() + kDivideCycles;
      break;
    case 0x1B:  // DIVU
      if (t == 0) {
        hi_ = s;
        lo_ = 0xFFFFFFFF;
      } else {
        hi_ = s % t;
        lo_ = s / t;
      }
      muldiv_ready_at_ = sched_.now() + kDivideCycles;
      break;
    case 0x20: {  // ADD
      u32 r = s + t;
      if (((s ^ r) & (t ^ r)) >> 31) exception(Exception::Overflow);
      else write_reg(d, r);
      break;
    }
    case 0x21: write_reg(d, s + t); break;  // ADDU
    case 0x22: {                            // SUB
      u32 r = s - t;
      if (((s ^ t) & (s ^ r)) >> 31) exception(Exception::Overflow);
      else write_reg(d, r);
      break;
    }
    case 0x23: write_reg(d, s - t); break;            // SUBU
    case 0x24: write_reg(d, s & t); break;            // AND
    case 0x25: write_reg(d, s | t); break;            // OR
    case 0x26: write_reg(d, s ^ t); break;            // XOR
    case 0x27: write_reg(d, ~(s | t)); break;         // NOR
    case 0x2A: write_reg(d, s32(s) < s32(t)); break;  // SLT
    case 0x2B: write_reg(d, s < t); break;            // SLTU
    default: exception(Exception::Reserved); break;
  }
}

template <class BusT>
void CpuT<BusT>::execute_bcondz(u32 instr) {
  using namespace cpu_detail;
  // BLTZ/BGEZ/BLTZAL/BGEZAL. The CPU decodes only bit 16 (greater-or-equal) and whether bits
  // 20-17 are 1000 (link); other rt values act as BLTZ/BGEZ (psx-spx "Jump Opcodes").
  const u32 r = rt(instr);
  const bool ge = r & 1;
  const bool link = (r & 0x1E) == 0x10;
  const u32 s = regs_[rs(instr)];
  const bool taken = ge ? s32(s) >= 0 : s32(s) < 0;
  if (link) write_reg(31, next_pc_);
  loop_branch(pc_ + (simm(instr) << 2), taken);
}

// Instructions for a coprocessor with no data path to the CPU: COP1/COP3 and LWC/SWC for 0, 1
// and 3. ps1-tests cpu/cop (hardware log tests/data/ps1-tests/cpu-cop.log) shows the unusable
// exception only while SR.CUn is clear, in kernel mode too, and nothing at all when it is set, for
// COP1, COP3, SWC0 and SWC3. With CUn set an LWCn still reads the word (a bus read with its
// timing and side effects) and an SWCn writes nothing, after Mednafen; both check alignment first.
template <class BusT>
void CpuT<BusT>::execute_absent_cop(u32 instr) {
  using namespace cpu_detail;
  const u32 cop = op(instr) & 3;
  if (!(cop0_.sr & (Cop0::kCU0 << cop))) {
    exception(Exception::CopUnusable, cop);
    return;
  }
  if (op(instr) < 0x30) return;  // COP1/COP3: no coprocessor takes the command
  const bool store = op(instr) >= 0x38;
  const u32 addr = regs_[rs(instr)] + simm(instr);
  if (!check_address(addr, 3, store ? Exception::AddressStore : Exception::AddressLoad) || store) return;
  u32 v;
  if constexpr (kLoadShadow) wait_load();
  if (!bus_.read32(addr, v)) exception(Exception::BusData);
}

template <class BusT>
void CpuT<BusT>::execute_cop0(u32 instr) {
  using namespace cpu_detail;
  if ((cop0_.sr & Cop0::kKUc) && !(cop0_.sr & Cop0::kCU0)) {
    exception(Exception::CopUnusable, 0);
    return;
  }
  switch (rs(instr)) {
    case 0x00: {  // MFC0: the value arrives after a load delay
      u32 v;
      switch (rd(instr)) {
        case 3: v = cop0_.bpc; break;
        case 5: v = cop0_.bda; break;
        case 6: v = cop0_.jumpdest; break;
        case 7: v = cop0_.dcic; break;
        case 8: v = cop0_.badvaddr; break;
        case 9: v = cop0_.bdam; break;
        case 11: v = cop0_.bpcm; break;
        case 12: v = cop0_.sr; break;
        case 13: v = cop0_.cause; break;
        case 14: v = cop0_.epc; break;
        case 15: v = Cop0::kPRId; break;
        case 0: case 1: case 2: case 4: case 10: exception(Exception::Reserved); return;
        default: return;  // cop0r16-r31: no exception (psx-spx "COP0 - Misc"); rt keeps its value
      }
      delayed_load(rt(instr), v);
      break;
    }
    case 0x04: {  // MTC0
      u32 v = regs_[rt(instr)];
      switch (rd(instr)) {
        case 3: cop0_.bpc = v; break;
        case 5: cop0_.bda = v; break;
        case 7: cop0_.dcic = v & Cop0::kDcicWritable; break;
        case 9: cop0_.bdam = v; break;
        case 11: cop0_.bpcm = v; break;
        case 12: cop0_.sr = v; break;
        case 13: cop0_.cause = (cop0_.cause & ~Cop0::kCauseWritable) | (v & Cop0::kCauseWritable); break;
        default: break;  // read-only or unused registers ignore writes
      }
      break;
    }
    case 0x02:
    case 0x06: exception(Exception::Reserved); break;  // CFC0/CTC0: cop0r32-r63 do not exist
    case 0x08:
    case 0x0C: exception(Exception::CopUnusable, 0); break;  // BC0F/BC0T (psx-spx "COP0 - Misc")
    default:
      if (rs(instr) >= 0x10) execute_cop0_command(instr);
      break;  // the other rs values do nothing, as in Mednafen
  }
}

// COP0 commands (bit 25 set, any rs from 10h): only RFE exists; the TLB commands TLBR, TLBWI,
// TLBWR and TLBP (01h, 02h, 06h, 08h) raise RI (psx-spx "COP0 - Misc"), and the rest do nothing:
// ps1-tests cpu/cop runs command 0 with rs = 1Fh on hardware and sees no exception. The command
// is decoded from bits 0-4, as Mednafen does.
template <class BusT>
void CpuT<BusT>::execute_cop0_command(u32 instr) {
  switch (instr & 0x1F) {
    case 0x10:  // RFE: pop the KU/IE stack
      cop0_.sr = (cop0_.sr & ~0xFu) | ((cop0_.sr >> 2) & 0xF);
      resume_pc_ = pc_;  // in a JR's delay slot: where the JR goes
      break;
    case 0x01:
    case 0x02:
    case 0x06:
    case 0x08: exception(Exception::Reserved); break;
    default: break;
  }
}

template <class BusT>
void CpuT<BusT>::execute_cop2(u32 instr) {
  using namespace cpu_detail;
  if (!(cop0_.sr & Cop0::kCU2)) {
    exception(Exception::CopUnusable, 2);
    return;
  }
  if (instr & (1u << 25)) {  // imm25: a GTE command; the CPU waits for the previous one
    wait_gte();
    gte_ready_at_ = sched_.now() + gte_.execute(instr & 0x1FFFFFF);
    return;
  }
  switch (rs(instr)) {
    case 0x00: wait_gte(); delayed_load(rt(instr), gte_.read_data(rd(instr))); break;     // MFC2
    case 0x02: wait_gte(); delayed_load(rt(instr), gte_.read_control(rd(instr))); break;  // CFC2
    case 0x04: wait_gte(); gte_.write_data(rd(instr), regs_[rt(instr)]); break;           // MTC2
    case 0x06: wait_gte(); gte_.write_control(rd(instr), regs_[rt(instr)]); break;        // CTC2
    default: exception(Exception::Reserved); break;
  }
}

template <class BusT>
void CpuT<BusT>::do_state(StateIO& s) {
  // Version 2 added the load shadow; a version-1 state was made with loads that completed at
  // once, so none is in flight.
  const u32 version = s.section("CPU ", 2, 1);
  s.pod(regs_);
  s.pod(hi_), s.pod(lo_), s.pod(pc_), s.pod(next_pc_), s.pod(current_pc_);
  s.boolean(in_delay_slot_), s.boolean(next_in_delay_);
  s.pod(load_reg_), s.pod(load_val_), s.pod(new_load_reg_), s.pod(new_load_val_);
  s.pod(muldiv_ready_at_), s.pod(gte_ready_at_), s.pod(instructions_);
  s.boolean(hook_armed_), s.pod(hook_pc_);
  s.pod_since(version, 2, load_done_at_, Cycles{0});
  s.pod_since(version, 2, shadow_reg_, u32{0});
  if (s.loading() && (load_reg_ > 31 || new_load_reg_ > 31 || shadow_reg_ > 31))
    s.fail("CPU load-delay register out of range");
  // A load's access, a multiply or divide and a GTE command end at most this far after the
  // scheduler's time (loaded before the CPU), which the recompiler's deadline budget relies on.
  const Cycles now = sched_.now();
  if (s.loading() && (load_done_at_ > now + kLoadBus + 1 || muldiv_ready_at_ > now + cpu_detail::kDivideCycles ||
                      gte_ready_at_ > now + Gte::kLongestCommandCycles))
    s.fail("CPU load, multiply/divide or GTE end time too far ahead of the scheduler's time");
  cop0_.do_state(s);
  s.end_section("CPU ");
}

}  // namespace psx
