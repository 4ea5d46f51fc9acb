// Idle-loop skipping: recording one iteration, proving the next ones repeat it, skipping them.
#include "core/cpu/idle_skip.h"

#include <algorithm>

#include "core/bus.h"
#include "core/cpu/cpu.h"
#include "core/cpu/idle_proof.h"

namespace psx {

// The CPU's members are instantiated once, in cpu.cpp.
extern template class CpuT<Bus>;

namespace {

// The instruction word at `vaddr` as the interpreter would fetch it, without timing or i-cache.
bool peek_code(Bus& bus, u32 vaddr, u32& word) {
  const u32 p = Bus::physical(vaddr);
  if (vaddr & 3) return false;
  if (p < 0x00800000) {
    word = load_le32(bus.ram() + (p & (Bus::kRamSize - 1)));
    return true;
  }
  if (p >= 0x1FC00000 && p < 0x1FC00000 + Bus::kBiosSize) {
    word = load_le32(bus.bios() + (p - 0x1FC00000));
    return true;
  }
  return false;
}

// I/O registers whose read changes nothing and whose value changes only when an event runs or
// the CPU writes somewhere (psx-spx register descriptions; the devices' io_read confirm it):
// memory control, RAM_SIZE, I_STAT/I_MASK, every DMA register, the CD-ROM status and interrupt
// enable/flag registers (not the response or data FIFOs), GPUSTAT (not GPUREAD), SPUCNT and
// SPUSTAT. Timer counters (they count between events), SIO (baud timer, RX FIFO pops) and every
// FIFO are left out.
bool pure_io_register(u32 p, u32 width) {
  if (p >= 0x1F801000 && p < 0x1F801024) return true;
  if (p >= 0x1F801060 && p < 0x1F801064) return true;
  if (p >= 0x1F801070 && p < 0x1F801078) return true;
  if (p >= 0x1F801080 && p < 0x1F801100) return true;
  if (p == 0x1F801800 || p == 0x1F801803) return true;
  if (p >= 0x1F801814 && p < 0x1F801818) return true;
  if ((p == 0x1F801DAA || p == 0x1F801DAE) && width <= 2) return true;
  return false;
}

// A load the loop may make: no exception, and a value that cannot change before the next event.
bool pure_load(u32 sr, u32 vaddr, u32 width) {
  if (vaddr & (width - 1)) return false;
  if ((sr & Cop0::kKUc) && (vaddr & 0x80000000)) return false;
  if (vaddr >= 0xC0000000) return false;
  const u32 p = Bus::physical(vaddr);
  if (p < 0x00800000) return true;
  if (p >= 0x1F800000 && p < 0x1F800000 + Bus::kScratchSize) return vaddr < 0xA0000000;
  if (p >= 0x1FC00000 && p < 0x1FC00000 + Bus::kBiosSize) return true;
  return pure_io_register(p, width);
}

u32 load_width(u32 instr) {
  switch (instr >> 26) {
    case 0x20: case 0x24: return 1;  // LB, LBU
    case 0x21: case 0x25: return 2;  // LH, LHU
    case 0x23: return 4;             // LW
    default: return 0;
  }
}

}  // namespace

void IdleSkip::at_loop_head(Cpu& cpu) {
  const u32 head = cpu.pc_;
  const u64 before = cpu.instructions_;
  if (head == backoff_head_ && backoff_visits_ > 0) {
    --backoff_visits_;
  } else {
    switch (examine(cpu)) {
      case Outcome::Skipped:
        if (head == backoff_head_) backoff_failures_ = 0;
        break;
      case Outcome::Retry:
        backoff_failures_ = head == backoff_head_ ? std::min(backoff_failures_ + 1, 8u) : 1;
        backoff_head_ = head;
        backoff_visits_ = (1u << backoff_failures_) - 1;
        break;
      case Outcome::Reject:
        cpu.idle_rejected_[(head >> 2) % cpu.idle_rejected_.size()] = head;
        break;
    }
  }
  // The run loop calls here only when it would step; make sure it does.
  if (cpu.instructions_ == before) cpu.step();
}

IdleSkip::Outcome IdleSkip::examine(Cpu& cpu) {
  Bus& bus = cpu.bus_;
  Scheduler& sched = cpu.sched_;
  const u32 head = cpu.pc_;
  if (cpu.next_in_delay_ || cpu.hook_armed_ || bus.dcache_mode() || cpu.interrupt_pending() ||
      (cpu.cop0_.dcic & (Cop0::kDcicPCE | Cop0::kDcicDAE)))
    return Outcome::Retry;

  // 1. Execute one iteration, vetting each instruction before it runs.
  const Cycles deadline = sched.next_deadline();
  const Cycles t0 = sched.now();
  const u64 i0 = cpu.instructions_;
  const std::array<u32, 32> regs0 = cpu.regs_;
  const u32 load0[4] = {cpu.load_reg_, cpu.load_val_, cpu.new_load_reg_, cpu.new_load_val_};
  const ICache icache0 = bus.icache();
  path_len_ = 0;
  do {
    if (cpu.stop_ || sched.now() >= deadline) return Outcome::Retry;
    if (path_len_ == kMaxPath) return Outcome::Reject;
    u32 instr;
    if (!peek_code(bus, cpu.pc_, instr)) return Outcome::Reject;
    IdleStep& st = path_[path_len_++];
    st = {cpu.pc_, instr, 0, 0};
    const IdleProof::Kind kind = IdleProof::classify(instr);
    if (kind == IdleProof::Kind::Other) return Outcome::Reject;
    if (kind == IdleProof::Kind::Branch && cpu.next_in_delay_) return Outcome::Reject;
    const u32 width = load_width(instr);
    if (width) {
      st.load_addr = cpu.regs_[(instr >> 21) & 31] + static_cast<u32>(static_cast<s16>(instr & 0xFFFF));
      if (!pure_load(cpu.cop0_.sr, st.load_addr, width)) return Outcome::Reject;
    }
    cpu.step();
    st.load_value = cpu.load_val_;
    if (cpu.hook_armed_) return Outcome::Reject;
  } while (cpu.pc_ != head || cpu.next_in_delay_);

  // The iteration ran without an event falling due (events only run at or after the deadline),
  // filled no i-cache line (a fill changes its line's tag), and left the load pipeline as it was.
  const Cycles t1 = sched.now();
  if (t1 >= deadline || !(bus.icache() == icache0)) return Outcome::Retry;
  const u32 load1[4] = {cpu.load_reg_, cpu.load_val_, cpu.new_load_reg_, cpu.new_load_val_};
  if (!std::equal(load0, load0 + 4, load1)) return Outcome::Retry;

  // 2. Prove the following iterations repeat it, each adding the same step to the registers.
  IdleProof proof(regs0, cpu.regs_, cpu.load_reg_, cpu.load_val_);
  if (!proof.run(path_.data(), path_len_)) return Outcome::Retry;

  // 3. Skip whole iterations, ending before the deadline so the event's iteration is interpreted.
  const Cycles cost = t1 - t0;
  const u64 steps = cpu.instructions_ - i0;
  const u64 by_time = (deadline - 1 - t1) / cost;
  const u64 n = proof.max_k() < by_time ? proof.max_k() + 1 : by_time;
  if (n == 0) return Outcome::Retry;
  for (u32 i = 1; i < 32; ++i) cpu.regs_[i] += static_cast<u32>(n) * (cpu.regs_[i] - regs0[i]);
  sched.advance(n * cost);
  cpu.instructions_ += n * steps;
  ++stats_.skips;
  stats_.iterations += n;
  stats_.cycles += n * cost;
  return Outcome::Skipped;
}

}  // namespace psx
