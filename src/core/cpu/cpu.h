// The R3000A CPU core: a MIPS I interpreter with the PlayStation's load and branch delay slots,
// exceptions, COP0 and the COP2 (GTE) instruction interface. It is a template over the bus so
// that unit tests can run it against a scripted bus; the console instantiates it with Bus.
#pragma once
#include <array>
#include <type_traits>

#include "core/cpu/cop0.h"
#include "core/cpu/decode.h"
#include "core/gte/gte.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class Bus;
class IdleSkip;
template <class BusT>
class RecompilerT;

// Called before the instruction at a hooked address runs (the BIOS call vectors A0h/B0h/C0h and
// one extra address, e.g. the shell entry 0x80030000). A hook may redirect the CPU with set_pc().
class CpuHooks {
 public:
  virtual ~CpuHooks() = default;
  virtual void on_reach(u32 pc) = 0;
};

template <class BusT>
class CpuT {
  // The console's bus models load timing; the unit tests' scripted buses do not.
  static constexpr bool kLoadShadow = std::is_same_v<BusT, Bus>;

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

  // The recompiler (recompiler/recompiler.h) runs run()'s instructions from compiled blocks; with
  // nullptr run() interprets. Either way the machine state evolves identically.
  void set_recompiler(RecompilerT<BusT>* r) { recompiler_ = r; }
  bool recompiler_enabled() const { return recompiler_ != nullptr; }
  // The HLE kernel's ReturnFromException has just set the pc (as RFE in a jump's delay slot
  // does for a BIOS in ROM): see resume_pc_.
  void note_exception_return() { resume_pc_ = pc_; }

 private:
  friend class IdleSkip;
  friend class RecompilerT<BusT>;
  // A short backward branch or jump marks its target as a loop head worth examining.
  static constexpr u32 kIdleLoopBytes = 256;
  static constexpr u32 kNoLoopHead = 1;  // never equals an aligned pc
  // Whether run()'s pass hands the CPU to IdleSkip: at a loop head with skipping on. pc_ may be
  // odd too (a jump to an odd address, whose fetch then raises the address error), so equality
  // with kNoLoopHead is not a loop head; tested second, as pc_ rarely equals loop_head_.
  bool at_loop_head() const { return pc_ == loop_head_ && loop_head_ != kNoLoopHead && idle_skip_; }
  // step() after its hook and interrupt checks: one instruction at pc_, its timing and the load
  // delay slot's bookkeeping.
  void execute_at_pc();
  void execute(u32 instr);
  void execute_special(u32 instr);
  void execute_bcondz(u32 instr);
  void execute_cop0(u32 instr);
  void execute_cop0_command(u32 instr);
  void execute_absent_cop(u32 instr);
  void execute_cop2(u32 instr);
  // Vectors at BEV ? 0xBFC00100 : 0x80000000 plus 0x80 (general) or 0x40 (debug break).
  static constexpr u32 kGeneralVector = 0x80, kDebugVector = 0x40;
  void exception(Exception code, u32 coprocessor = 0, u32 vector_offset = kGeneralVector);
  bool exec_break();
  bool data_break(u32 first, u32 count, bool write);
  void take_data_break();
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
    if (hooked(target)) {
      hook_armed_ = true;
      hook_pc_ = target;
    }
  }
  // Whether a jump to target arms a hook: the BIOS's A0h/B0h/C0h function vectors, extra_hook_pc_.
  bool hooked(u32 target) const {
    const u32 p = target & 0x1FFFFFFF;
    return hooks_ && (p == 0xA0 || p == 0xB0 || p == 0xC0 || target == extra_hook_pc_);
  }
  void wait_muldiv();
  void wait_gte();
  // Load shadow (the comment at kLoadIssue). timed_read makes a load's bus read and charges its
  // time; wait_load holds another memory access until a load in flight is done; shadow_stall
  // holds an instruction that reads the register a load in flight is bringing.
  // `first` and `count`: the bytes of the word LWL/LWR merge (Bus::read_merged()).
  bool timed_read(u32 addr, u32 width, u32 rt, u32& v, u32 first = 0, u32 count = 4);
  // The bus-access tail of a load through the bus interface (the comment at kIoTail), set once
  // its read is made: load_done_at_ as a RAM load's shadow leaves it. `reach`
  // (cpu_detail::kTailUnknown ...): what a caller that knows the next instructions (the
  // recompiler, from the words it compiled) already knows of which one meets the tail. rt: the
  // loaded register, whose reader after the delay slot waits for the tail (shadow_stall()).
  void io_tail(u32 addr, u32 rt, u32 reach = cpu_detail::kTailUnknown) {
    if constexpr (kLoadShadow) {
      using namespace cpu_detail;
      if (!BusT::bus_load(addr) || !bus_.cached_code(current_pc_)) return;
      if (reach == kTailUnknown || reach == kTailPastFirst) reach = tail_reach(reach, rt);
      load_done_at_ = sched_.now() + kIoTail + reach;
      shadow_reg_ = rt;
    }
  }
  // The tail's reach (1, 2 or 3) from the instructions at pc_ and pc_ + 4 that `known` leaves open.
  u32 tail_reach(u32 known, u32 rt) const;
  // Whether the instruction at vaddr meets such a tail: its fetch goes to memory, it is a load,
  // or it reads `reader` (nonzero: the loaded register, for the second instruction after the load).
  bool meets_tail(u32 vaddr, u32 reader = 0) const;
  void wait_load() {
    if (sched_.now() < load_done_at_) sched_.advance(load_done_at_ - sched_.now());
  }
  void shadow_stall(u32 instr);
  bool fetch(u32& instr) {
    if constexpr (kLoadShadow) return bus_.fetch(pc_, instr, load_done_at_);  // a miss waits
    else return bus_.fetch(pc_, instr);
  }
  void load(u32 instr, u32 width, bool sign);
  void load_unaligned(u32 instr, bool left);
  void store(u32 instr, u32 width);
  void store_unaligned(u32 instr, bool left);
  bool write_bytes(u32 base, u32 first, u32 last, u32 data);
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
  // Load timing (R3000A, code running from the i-cache, loads from RAM), after hardware
  // measurements by rustation's author (gist.github.com/simias/a4c3fa560de72e67a5b0b2ce9cf0298c;
  // cycles from the sequence's start until every load has completed):
  //   lw;nop 8 | lw t0;lw t1;nop 14 | lw t0;lw t0;nop 15 | three lw, other registers, + nop 20,
  //   the same register 22 | lw + 6 nops 8, + 7 nops 9 | lw t0; move t4,t0 (delay slot) 8 |
  //   lw t0; nop; move t4,t0; 4 nops 13.
  // Model: a load instruction takes kLoadIssue cycles and its RAM access starts one cycle after
  // that, or when the previous load's access ends (a cycle later still for a load in the delay
  // slot of a load to the same register), and lasts kLoadBus cycles; the CPU waits only to start
  // that access, so one load waits at a time. Following instructions run in the access's shadow,
  // except that another memory access (a load, an i-cache miss) waits for it to end, and an
  // instruction after the delay slot that reads the loaded register ends no earlier than it (the
  // value is there a cycle before: the instruction executes in the access's last cycle), as
  // the last measurement has it.
  // Timed as tests/roms/cpu_load_timing does (timer reads around the sequence,
  // an empty sequence's time subtracted; the closing read's first cycle overlaps the wait), a
  // sequence takes max(e, C - 1): e when its instructions end, C when its last access ends.
  // Worked through: lw at 0 accesses 3..9, so lw;nop takes 8; lw;lw accesses 3..9, 9..15: 14;
  // 15 for the same register; lw + 7 nops: the nops end at 2 + 7 = 9; lw;nop;use: the use ends
  // at 9, one cycle later than lw;nop would.
  // Only loads from RAM made by cached code are modelled so: uncached code (KSEG1, the BIOS
  // running from ROM) and other regions keep the synchronous read times of Bus::read, and stores
  // never wait (the write queue).
  static constexpr Cycles kLoadIssue = 2, kLoadBus = 6;
  // Loads through the bus interface (I/O ports, SPU, CD-ROM, expansion, BIOS ROM) made by cached
  // code, after pcsx-redux's hardware-checked src/mips/tests/load-timings: 32 loads from I_STAT,
  // each followed by s nops, cost 164, 196, 228, 228, 228, 260, 292, 324 cycles for s = 0..7
  // (32 per-load costs, and 4 for the test's two counter reads). The read takes its region's
  // time (Bus::read(): 2 cycles past the issue for an on-chip port), then the access holds the
  // bus kIoTail cycles more, which the third and fourth instructions after the load hide, one
  // each; the next load or fetch from memory meets what is left of it, the whole kIoTail as the
  // first or second instruction after the load. In the load-shadow terms above, io_tail() ends
  // the access kIoTail + 3 cycles after the read, or kIoTail + 1 (+ 2) when the first (second)
  // instruction meets it. Worked through, per load: lw;lw 1 + 2 + 2 = 5; lw + 1 nop 6; + 2 nops
  // 3 + 2 + 2 = 7; + 3 nops 3 + 3 + 1 = 7 (the third nop hides a cycle); + 4 nops 7; + 5 nops 8.
  // ps1-tests cpu/access-time's loop (load, bnez, nop, nop, addiu) hides the tail: 3 a load from
  // a port, as on the console; its 32-bit SPU read, an LWL+LWR pair 2 instructions apart, is two
  // 16-bit reads (18 each, Bus::read_merged()) and the tail met whole, then in part: 39, as on
  // the console. A reader of the loaded register after the delay slot waits for the tail's end,
  // and the second instruction after the load meets the tail when it is that reader: 32 x (lw
  // I_STAT + 8 instructions, an addiu of the register 2nd..8th) cost 420, 420, 388, 356 ... in
  // load-timings' loadInterlocked, so a load 13, 13, 12, 11 ... cycles: reader 2nd, reach 2, the
  // tail ends 4 cycles after the read, where the reader would end at 2 (+2); 3rd, reach 3, ends
  // at 5 for 3 (+2); 4th +1; 5th on, none. ps1-tests dma/chopping's 64 pairs fit only with this
  // (its poll loop, a reader 2nd, at 10 cycles); ps1-tests timers stands against it
  // (docs/fidelity.md).
  static constexpr Cycles kIoTail = 2;
  Cycles load_done_at_ = 0;  // when the last shadowed load's RAM access ends
  u32 shadow_reg_ = 0;       // its destination register, until an instruction waits for it or
                             // sees the access ended (0 then: nothing left to check)
  Cop0 cop0_;
  u64 instructions_ = 0;
  bool stop_ = false;
  bool hook_armed_ = false;
  // The recompiler's written-code flag (CodePages::keep_flag_at): here, so that compiled blocks
  // test it with stop_ and hook_armed_ in one compare.
  bool code_written_ = false;
  u32 hook_pc_ = 0;
  // Host-side idle-skip bookkeeping (not machine state, not saved).
  IdleSkip* idle_skip_ = nullptr;
  RecompilerT<BusT>* recompiler_ = nullptr;
  u32 loop_head_ = kNoLoopHead;
  // Where the CPU last took up a program in the middle of its flow: where run() starts (the
  // deadline stopped the last run() wherever it fell) or where a return from an exception went,
  // then each instruction after it up to the end of a branch's delay slot (kNoResume after that).
  // The recompiler interprets these where they lie inside a compiled block instead of compiling
  // a block from each such point. A host-side hint like the two above, not saved: blocks and the
  // interpreter compute the same.
  static constexpr u32 kNoResume = 1;  // never an aligned pc
  u32 resume_pc_ = kNoResume;
};

using Cpu = CpuT<Bus>;

}  // namespace psx
