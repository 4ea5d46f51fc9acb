// The R3000A CPU core: a MIPS I interpreter with the PlayStation's load and branch delay slots,
// exceptions, COP0 and the COP2 (GTE) instruction interface. It is a template over the bus so
// that unit tests can run it against a scripted bus; the console instantiates it with Bus.
#pragma once
#include <array>

#include "core/cpu/cop0.h"
#include "core/gte/gte.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class Bus;
class IdleSkip;

// Called before the instruction at a hooked address runs (the BIOS call vectors A0h/B0h/C0h and
// one extra address, e.g. the shell entry 0x80030000). A hook may redirect the CPU with set_pc().
class CpuHooks {
 public:
  virtual ~CpuHooks() = default;
  virtual void on_reach(u32 pc) = 0;
};

template <class BusT>
class CpuT {
 public:
  static constexpr u32 kResetVector = 0xBFC00000;

  CpuT(BusT& bus, Scheduler& sched, InterruptController& irq, Gte& gte)
      : bus_(bus), sched_(sched), irq_(irq), gte_(gte) {}

  void reset();
  // Runs instructions until the scheduler's next deadline or until stop() is called.
  void run();
  // Executes one instruction (or takes a pending interrupt instead).
  void step();
  void stop() { stop_ = true; }

  void set_hooks(CpuHooks* hooks, u32 extra_hook_pc) {
    hooks_ = hooks;
    extra_hook_pc_ = extra_hook_pc;
  }

  // Architectural state, for the HLE kernel, EXE loading, tests and debuggers.
  u32 reg(u32 r) const { return regs_[r]; }
  void set_reg(u32 r, u32 v) {
    regs_[r] = v;
    regs_[0] = 0;
  }
  u32 pc() const { return pc_; }
  // Jumps immediately (no delay slot), dropping any pending branch or load.
  void set_pc(u32 pc);
  u32 hi() const { return hi_; }
  u32 lo() const { return lo_; }
  void set_hi(u32 v) { hi_ = v; }
  void set_lo(u32 v) { lo_ = v; }
  Cop0& cop0() { return cop0_; }
  u64 instructions() const { return instructions_; }

  // The pipeline state between two instructions, as the single-step test data describes it.
  struct Pending {
    bool in_delay_slot = false;  // the instruction at pc() is a branch delay slot
    u32 next_pc = 0;             // where execution goes after the instruction at pc()
    u32 load_reg = 0;            // a load issued by the previous instruction (0 = none)
    u32 load_value = 0;
  };
  Pending pending() const { return {next_in_delay_, next_pc_, load_reg_, load_val_}; }
  void set_pending(const Pending& p) {
    next_in_delay_ = p.in_delay_slot;
    next_pc_ = p.next_pc;
    load_reg_ = p.load_reg;
    load_val_ = p.load_value;
  }

  void do_state(StateIO& s);

  // Idle-loop skipping (idle_skip.h): on with a skipper, off (plain interpretation) with nullptr.
  // Skipping is exact, so it changes how fast the console runs, never what it computes.
  void set_idle_skip(IdleSkip* skip) { idle_skip_ = skip; }
  bool idle_skip_enabled() const { return idle_skip_ != nullptr; }

 private:
  friend class IdleSkip;
  // A short backward branch or jump marks its target as a loop head worth examining.
  static constexpr u32 kIdleLoopBytes = 256;
  static constexpr u32 kNoLoopHead = 1;  // never equals an aligned pc
  void execute(u32 instr);
  void execute_special(u32 instr);
  void execute_bcondz(u32 instr);
  void execute_cop0(u32 instr);
  void execute_cop2(u32 instr);
  // Vectors at BEV ? 0xBFC00100 : 0x80000000 plus 0x80 (general) or 0x40 (debug break).
  static constexpr u32 kGeneralVector = 0x80, kDebugVector = 0x40;
  void exception(Exception code, u32 coprocessor = 0, u32 vector_offset = kGeneralVector);
  bool exec_break();
  bool data_break(u32 first, u32 count, bool write);
  bool debug_break(u32 status);
  void take_interrupt();
  bool interrupt_pending() const;

  // Register writes by ordinary instructions: a pending load to the same register loses.
  void write_reg(u32 r, u32 v) {
    regs_[r] = v;
    if (load_reg_ == r) load_reg_ = 0;
  }
  // Loads land after the next instruction (the load delay slot).
  void delayed_load(u32 r, u32 v) {
    if (load_reg_ == r) load_reg_ = 0;
    new_load_reg_ = r;
    new_load_val_ = v;
  }
  void branch(u32 target, bool taken) {
    next_in_delay_ = true;
    if (!taken) return;
    next_pc_ = target;
    arm_hook(target);
  }
  // A branch that may close a loop: a taken one to a little before itself names a loop head.
  void loop_branch(u32 target, bool taken) {
    branch(target, taken);
    if (taken && target <= current_pc_ && current_pc_ - target < kIdleLoopBytes) loop_head_ = target;
  }
  void arm_hook(u32 target) {
    u32 p = target & 0x1FFFFFFF;
    if (hooks_ && (p == 0xA0 || p == 0xB0 || p == 0xC0 || target == extra_hook_pc_)) {
      hook_armed_ = true;
      hook_pc_ = target;
    }
  }
  void wait_muldiv();
  void wait_gte();
  void load(u32 instr, u32 width, bool sign);
  void load_unaligned(u32 instr, bool left);
  void store(u32 instr, u32 width);
  void store_unaligned(u32 instr, bool left);
  bool check_address(u32 addr, u32 align_mask, Exception code);

  BusT& bus_;
  Scheduler& sched_;
  InterruptController& irq_;
  Gte& gte_;
  CpuHooks* hooks_ = nullptr;
  u32 extra_hook_pc_ = 0xFFFFFFFF;

  std::array<u32, 32> regs_{};
  u32 hi_ = 0, lo_ = 0;
  u32 pc_ = kResetVector;         // instruction about to execute
  u32 next_pc_ = kResetVector + 4;
  u32 current_pc_ = 0;            // instruction executing now (for EPC)
  bool in_delay_slot_ = false;    // the executing instruction is in a delay slot
  bool next_in_delay_ = false;
  u32 load_reg_ = 0, load_val_ = 0;
  u32 new_load_reg_ = 0, new_load_val_ = 0;
  Cycles muldiv_ready_at_ = 0;
  Cycles gte_ready_at_ = 0;
  Cop0 cop0_;
  u64 instructions_ = 0;
  bool stop_ = false;
  bool hook_armed_ = false;
  u32 hook_pc_ = 0;
  // Host-side idle-skip bookkeeping (not machine state, not saved).
  IdleSkip* idle_skip_ = nullptr;
  u32 loop_head_ = kNoLoopHead;
};

using Cpu = CpuT<Bus>;

}  // namespace psx
