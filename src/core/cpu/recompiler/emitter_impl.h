// The code generator behind BlockEmitter (block_emitter.h), shared by its sources:
// block_emitter.cpp (a block's frame, the segment guard, each instruction's bookkeeping, ALU
// operations), block_emitter_chain.cpp (the block's end and the jump to the next block),
// block_emitter_branch.cpp (branches and jumps), block_emitter_icache.cpp (i-cache
// line checks and fills), block_emitter_memory.cpp (loads, stores, the load delay slot, HI/LO
// moves), block_emitter_muldiv.cpp (multiplies and divides), block_emitter_cop2.cpp (GTE moves and
// commands) and block_emitter_timing.cpp (the deadline's budget, the cycles owed, the load
// shadow). Only they include this header (and with it xbyak).
// Registers while a block runs:
// rbx = the context (the CPU) plus Layout::bias, r12 = the i-cache's tags (its words lie at a
// fixed distance from them), r10d = the value of the load the previous instruction made
// (load_val_, which native() lands from r10d where nothing called out since), r13d = a load's or
// store's address (past address_checks(), its offset from Layout::ram), r14 = the scheduler's
// time and r15 = its deadline, rbp = the CPU's instruction count (the cells in memory are stale
// while native code runs: flush() writes the time and the count back before anything outside the
// block can look, reload() reads all three after a call).
// Within a native segment rbp stays the count at the segment's start: instruction k adds nothing,
// and every way out of the segment adds the k instructions run (its end, a slow or fallback call).
// Likewise r14 runs behind the time by the cycles the emitter knows are owed (Impl::owed).
// r8b = whether a split branch is taken, from the branch to its delay slot's end (split_end(),
// split_mid()), where the flags no longer say so (Impl::split_cond).
#pragma once
#include <xbyak/xbyak.h>

#include <array>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

#include "core/cpu/recompiler/block_emitter.h"
#include "core/gte/gte.h"

namespace psx {

// What native code knows of the load delay slot when an instruction starts. At a segment's
// first instruction nothing (`dynamic`: load_reg_ and load_val_ are read where they are); after
// that, whether the previous instruction was a load and to which register (load_reg_ is then
// that register and load_val_ its value; otherwise both are zero). new_load_* are always zero
// between instructions.
struct Pipe {
  bool dynamic = true;
  bool after_load = false;
  u32 load_reg = 0;
};

// What instruction k of a segment does about the load shadow (CpuT::shadow_stall). A load
// leaves its access ending at most kLoadIssue + kLoadBus - 1 cycles after it (7), and each
// instruction takes at least one: by the 7th instruction after the last load (or after the
// segment's start, which may follow one) time has reached the access's end, so the check there
// always clears the shadow (`clear`), and after it the shadow is known to be clear (`none`).
enum class Shadow : u8 { check, clear, none };

// One native segment's pieces emitted after the block's main path: its steps as calls (the slow
// path; `slow[k]` enters it at instruction k), a load's or store's call when the native code
// does not make the access (`fallback[k]`, back to the native code at `resume[k + 1]`) and the
// shadow-stall stubs.
struct Segment {
  size_t first, count;
  std::vector<Shadow> shadow;  // per instruction
  // shadowed[k], where instruction k checks the shadow and a load of the segment lies within
  // reach before it: that load's rt (see shadow_known()); kUnknownShadow elsewhere.
  static constexpr u32 kUnknownShadow = ~0u;
  std::vector<u32> shadowed;
  // budget[k]: the most cycles from instruction k's start to the last instruction's start, on top
  // of the time then (budget_check()).
  std::vector<u32> budget;
  Xbyak::Label end;
  std::vector<Xbyak::Label> slow, fallback, resume, stall, stall_back;
  // An i-cache line the run reaches at instruction k missing: fill_stub() fills it natively at
  // `fill[k]` and goes on at `filled[k]` (past the line check), or sends k to its slow path.
  std::vector<Xbyak::Label> fill, filled;
  // slow[k] entered from native code, which counts its instructions only where it leaves: the
  // count of instructions 0..k-1 is added first (native()).
  std::vector<Xbyak::Label> slow_native;
  std::vector<Pipe> pipe;  // per instruction
  // time_in[k]: the cycles native code owes r14 where instruction k starts (Impl::owed);
  // stall_owed[k]: those owed at instruction k's shadow check, which its stall stub keeps.
  std::vector<u32> time_in, stall_owed;
  // lazy[k]: instruction k's load (a delayed write, is_delayed()) stays in r10d alone, with
  // load_reg_ and load_val_ left zero, because instruction k + 1 lands it natively without
  // calling out (lazy_lands()); only that instruction's ways to a call write them (pending()).
  std::vector<bool> lazy;
  // eax_at[k]: the general register whose value eax holds where instruction k starts (0: none),
  // which a call resuming there (call_and_resume()) loads into eax.
  std::vector<u32> eax_at;
  // The block's last segment, ending in a branch whose target is known now and a delay slot
  // emitted once for each way (splits(), split_end()); the delay slot has no resume[] entry.
  bool split = false;
  // mid[k]: instruction k is a conditional branch split inside the block (BlockEmitter::goes_on(),
  // split_mid()): its delay slot is emitted once for each way, the taken one leaving the block.
  std::vector<bool> mid;
  bool ends_block = false;  // the block's native end: chain(true) follows the segment
};

struct BlockEmitter::Impl : Xbyak::CodeGenerator {
  explicit Impl(size_t bytes) : Xbyak::CodeGenerator(bytes), capacity(bytes) {}
  const size_t capacity;
  Layout lay{};
  Xbyak::Label* exit = nullptr;  // the block's epilogue
  // Rarely taken code of the block (a scratchpad access, a store into compiled code, the
  // machine_routine()s), emitted after the whole block so that the main path stays short;
  // labels it jumps to or from live in cold_labels until then.
  std::vector<std::function<void()>> cold;
  std::deque<Xbyak::Label> cold_labels;
  Xbyak::Label& cold_label() { return cold_labels.emplace_back(); }
  void emit_cold();

  Xbyak::Address reg(u32 r) { return dword[rbx + lay.regs + 4 * int(r)]; }
  // The general register whose value eax holds as native code runs (0: none): the one an
  // instruction has just written from eax. Reading it from eax instead of memory spares the
  // store-to-load forwarding on a chain of dependent instructions.
  u32 eax_reg = 0;
  bool in_eax(u32 r) const { return r != 0 && r == eax_reg; }
  // Register r as a source operand: eax where it holds r, else r's cell.
  template <class F>
  void with_reg(u32 r, F f) {
    if (in_eax(r)) f(eax);
    else f(reg(r));
  }
  void read_eax(u32 r) {
    if (!in_eax(r)) mov(eax, reg(r));
  }
  // eax = register a, ecx = register b.
  void read_pair(u32 a, u32 b) {
    if (in_eax(b) && !in_eax(a)) {
      mov(ecx, eax);
      mov(eax, reg(a));
      return;
    }
    read_eax(a);
    if (b == a) mov(ecx, eax);
    else mov(ecx, reg(b));
  }
  Xbyak::Address cpu32(int off) { return dword[rbx + off]; }
  std::optional<int> from_context(const void* p) const;
  Xbyak::RegExp host_at(const Xbyak::Reg64& index, bool via_rdx);
  Xbyak::RegExp word_at(NativeOp op);
  Xbyak::RegExp gte_at(u32 offset);
  void gte_read(const Gte::Field& f);
  void gte_write(const Gte::Field& f, const Xbyak::Reg32& value);
  Xbyak::Address cpu64(int off) { return qword[rbx + off]; }
  // Time lives in registers inside a block: `now` counts native instructions' cycles without a
  // memory read-modify-write per instruction and `deadline` is compared without loads.
  const Xbyak::Reg64& now = r14;
  const Xbyak::Reg64& deadline = r15;
  const Xbyak::Reg64& instructions = rbp;
  // Within a native segment r14 runs behind the time by `owed` cycles, known here: an instruction
  // counts its cycle only in `owed`, and r14 catches up (settle()) before anything reads or moves
  // it (a load, a wait, a shadow check that compares the time, the segment's end); the ways out
  // of a segment add what is owed there (Segment::time_in) and a call resuming it takes it off.
  u32 owed = 0;
  void flush();
  void reload();
  // A call to a function that is handed neither the CPU nor the scheduler (the GTE's, the code
  // pages'), so it can neither see nor move the time and count held in registers.
  void call_leaf(const void* fn);

  static bool is_branch(NativeOp op) { return op >= NativeOp::Beq; }
  static bool is_load(NativeOp op) { return op >= NativeOp::Lb && op <= NativeOp::Lwr; }
  static bool is_store(NativeOp op) { return op >= NativeOp::Sb && op <= NativeOp::Swr; }
  static bool is_store_or_swc2(NativeOp op) { return is_store(op) || op == NativeOp::Swc2; }
  static bool is_unaligned(NativeOp op) {
    return op == NativeOp::Lwl || op == NativeOp::Lwr || op == NativeOp::Swl || op == NativeOp::Swr;
  }
  static bool is_cop2(NativeOp op) { return op >= NativeOp::Mfc2 && op <= NativeOp::Swc2; }
  // Whether the instruction's native code leaves r10 alone: only a store (into compiled code),
  // LWC2/SWC2 and the GTE's instructions call out of the main path, which may change it.
  static bool keeps_r10(NativeOp op) { return !is_store_or_swc2(op) && op != NativeOp::Lwc2 && !is_cop2(op); }
  // The instructions that access memory (address_checks()).
  static bool is_memory(NativeOp op) {
    return is_load(op) || is_store_or_swc2(op) || op == NativeOp::Lwc2;
  }
  // Whether the instruction's result reaches rt after a load delay (delayed_load).
  static bool is_delayed(NativeOp op) { return is_load(op) || op == NativeOp::Mfc2 || op == NativeOp::Cfc2; }
  static u32 dest(NativeOp op, u32 i);

  // block_emitter.cpp
  void call_step(const Step& s);
  Xbyak::Label& step_routine();
  Xbyak::Label* step_entry = nullptr;  // this block's step_routine(), once emitted
  void alu(NativeOp op, u32 i);
  // block_emitter_branch.cpp
  void arm_hook_static(u32 target);
  void arm_hook_ecx();
  void branch(NativeOp op, u32 pc, u32 i, bool split);
  void taken(NativeOp op, u32 pc, u32 target);
  static u32 static_target(NativeOp op, u32 pc, u32 i);
  static bool splits(std::span<const Step> run, const Segment& seg);
  static bool splits_at(std::span<const Step> run, size_t k, const std::vector<Shadow>& shadow,
                        const std::vector<u32>& shadowed);
  void split_end(std::span<const Step> run, Segment& seg, std::optional<u32> budget);
  void split_mid(std::span<const Step> run, Segment& seg, size_t k, std::optional<u32> budget);
  // The flags a branch's compare leaves say it is taken when equal, not equal, less, greater or
  // equal, less or equal, greater (signed). jump_if() jumps when they say `c`.
  enum class Cond { e, ne, l, ge, le, g };
  static Cond negated(Cond c);
  void jump_if(Cond c, Xbyak::Label& to);
  // A split branch's condition while the flags its compare left still say whether it is taken:
  // split_mid() or split_end() jumps on them. Where code between them would change the flags,
  // keep_split_flags() saves the outcome in r8b first.
  std::optional<Cond> split_cond;
  void keep_split_flags();
  void unless_split_taken(Xbyak::Label& not_taken);
  // Emitting the delay slot of split_mid()'s taken way: for the load shadow it ends the block.
  bool exit_way = false;
  // Where the delay slot split_end() is emitting goes (pc_ after it), else empty.
  std::optional<u32> delay_dest;
  // Emitting the delay slot of split_mid()'s way on (not taken): it writes no pc_, next_pc_,
  // current_pc_ or in_delay_slot_, which the segment's stubs write where a call may read them
  // (sync_pc()); in_delay_slot_ stays 0 for the instructions after it.
  bool quiet_delay = false;
  // Where the delay slot of a J/JAL ending an unsplit segment goes (its branch wrote next_pc_
  // and next_in_delay_ as usual, for a call the delay slot may make), else empty.
  std::optional<u32> jump_dest;
  // The last instruction's shadow check is left to the chain that follows (shadow()).
  bool defer_shadow = false;
  // block_emitter.cpp
  // How a guard makes machine_checks(): inline (`all`), by calling machine_routine() (`routine`:
  // re-guards after slow calls, shorter code, compiled faster), or as the block's entry (`entry`:
  // its pc_checks() padded to kPcCheckBytes, its state_checks() and loop_head_check() padded to
  // kStateCheckBytes, where a clean chain() enters past them).
  enum class Checks { all, routine, entry };
  // guard() and line_check() send a missing line to `fill` where given (a fill_stub()'s entry),
  // which comes back to `filled`.
  // A guard with a `budget` makes budget_check() before the line check (and its fill).
  void guard(std::span<const Step> run, Xbyak::Label& fail, Checks checks, std::optional<u32> budget,
             Xbyak::Label* fill = nullptr, Xbyak::Label* filled = nullptr);
  static constexpr u32 kNeedsMemory = 1, kNeedsStores = 2, kNeedsCop2 = 4;
  // `framed`: emitted in the block's frame (rsp), where needs_checks() may use the vouch byte.
  void machine_checks(u32 needs, Xbyak::Label& fail, bool framed);
  void state_checks(Xbyak::Label& fail);
  void pc_checks(u32 first, Xbyak::Label& fail);
  void loop_head_check(u32 first, u32 bytes, Xbyak::Label& fail);
  void needs_checks(u32 needs, Xbyak::Label& fail, bool framed);
  void specific_needs_checks(u32 needs, Xbyak::Label& fail);
  // The frame's byte (from rsp) that vouches for every needs check since the last call.
  static constexpr int kVouched = 1;
  // Nops from getSize() up to `start` + `bytes`; throws where the code since `start` is longer.
  void pad_to(size_t start, size_t bytes, const char* what);
  Xbyak::Label& machine_routine(u32 needs);
  std::array<Xbyak::Label*, 8> routines{};  // this block's machine_routine() entries, by needs
  // block_emitter_icache.cpp
  void line_check(std::span<const Step> run, Xbyak::Label& fail, Xbyak::Label* fill = nullptr,
                  Xbyak::Label* filled = nullptr);
  Xbyak::Address icache_tag(u32 line);
  bool fills_natively(u32 pc) const;
  Xbyak::Label* fill_entry(u32 pc, Segment& seg, size_t k) const;
  void fill_stub(std::span<const Step> rest, size_t k, Segment& seg);
  // The bytes of a fill stub's jump back past the line check (a near jmp), which a refused fill
  // returns past, to the stub's jump to its slow path.
  static constexpr int kFillRefusal = 5;
  void fill_routine(u32 first);
  void fill_routines_once();
  // The buffer's fill_routine()s by the word a fill starts at, once emitted (null after clear()).
  std::array<const Xbyak::uint8*, 4> fill_routines{};
  // block_emitter.cpp
  // Instruction k of a segment, rest[0], with the segment's instructions after it.
  void native(std::span<const Step> rest, size_t k, bool after_branch, Segment& seg);
  void sync_pc(std::span<const Step> run, size_t j, const Segment& seg);
  void plan(std::span<const Step> run, Segment& seg);
  void segment_stubs(std::span<const Step> run, Segment& seg);
  void call_and_resume(std::span<const Step> run, size_t k, Segment& seg);
  // block_emitter_chain.cpp
  void chain(bool clean, Xbyak::Label* loop = nullptr, std::optional<u32> loop_budget = std::nullopt,
             std::optional<u32> target = std::nullopt);
  // The block being emitted: its pc, its entry, and whether a branch of it goes back there (a
  // clean chain() then tries its own clean entry first).
  u32 block_pc = 0;
  const Xbyak::uint8* block_entry = nullptr;
  bool self_loop = false;
  bool loops_natively = false;  // self_loop, and every step native: one segment
  Xbyak::Label& loop_head_routine();
  void loop_head_at_pc(std::optional<u32> target, Xbyak::Label& go_on, Xbyak::Label& back);
  Xbyak::Label* loop_head_entry = nullptr;  // this block's loop_head_routine(), once emitted
  bool ends_in_branch = false;  // the block's last instruction is a branch (without its delay slot)
  // The pc after the block's last instruction is aligned: it is no JR's or JALR's delay slot.
  bool aligned_end = true;
  // The link sites chain() emitted in this block (block_links.h).
  std::vector<BlockLinks::Site> links;
  // A block's entries: fn (a call from the dispatcher), fn + kPrologueBytes (a chain() from a
  // block that cannot vouch for pc_checks() and state_checks()), fn + kCleanEntry (a clean
  // chain(), past both and past the entry's loop_head_check()).
  // The pc checks take at most 29 bytes, the state and loop-head checks 163.
  static constexpr size_t kPrologueBytes = 64, kPcCheckBytes = 32, kStateCheckBytes = 168;
  static constexpr size_t kCleanEntry = kPrologueBytes + kPcCheckBytes + kStateCheckBytes;
  void prologue(const Layout& layout);
  void epilogue();
  // block_emitter_memory.cpp
  void memory_guard(bool stores, Xbyak::Label& fail);
  void address_checks(NativeOp op, u32 i, Xbyak::Label& slow);
  void load(NativeOp op, u32 i, const Pipe& pipe, bool bus_free);
  void io_address_check(const Step& s, Xbyak::Label& slow);
  void io_access(std::span<const Step> rest, size_t k);
  // Where an I/O load's bus tail ends as far as the words compiled tell (tail_plan()): `reach`
  // (cpu_detail::kTailUnknown ...), which holds where `next_line`, when set, is a hit.
  struct TailPlan {
    u32 reach = cpu_detail::kTailUnknown;
    std::optional<u32> next_line;
  };
  static TailPlan tail_plan(std::span<const Step> rest);
  void call_io_load(const Step& s, const TailPlan& plan);
  void io_checks(std::span<const Step> rest, size_t k, Segment& seg);
  void merge_unaligned(NativeOp op, u32 rt, const Pipe& pipe);
  void store(NativeOp op, u32 i);
  void lwc2(u32 i);
  void hilo(NativeOp op, u32 i);
  void commit(const Pipe& pipe, u32 cleared, bool load, u32 rt, bool r10_kept, bool lazy,
              bool pending_lazy);
  static bool lazy_lands(NativeOp op);
  void pending(std::span<const Step> run, size_t k, const Segment& seg);
  // block_emitter_muldiv.cpp
  void muldiv(NativeOp op, u32 i);
  // block_emitter_cop2.cpp
  void wait_gte();
  void cop2(NativeOp op, u32 i);
  // block_emitter_timing.cpp
  void settle();
  static bool uses_time(NativeOp op);
  u32 most_cycles(std::span<const Step> run, size_t j) const;
  u32 longest_wait(const Step& s) const;
  void budget_check(u32 budget, Xbyak::Label& fail);
  static std::vector<u32> shadowable_reads(const Step& s);
  static bool waits_for_load(const Step& s, u32 r, bool delay_slot);
  static bool has_stall(const Step& s, const Segment& seg, size_t k);
  static bool has_stall(const Step& s, Shadow shadow, u32 shadowed);
  static void plan_shadow(std::span<const Step> run, u32 reach, std::vector<Shadow>& shadow,
                          std::vector<u32>& shadowed);
  void shadow(const Step& s, size_t k, Segment& seg);
  void shadow_check(const Step& s, Xbyak::Label& stall);
  void shadow_known(const Step& s, const Pipe& pipe, u32 r, bool last);
  void stall_stub(size_t k, Segment& seg);
};

}  // namespace psx
