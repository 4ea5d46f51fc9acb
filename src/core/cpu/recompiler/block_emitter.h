// x86-64 code for compiled blocks, generated with xbyak into one executable buffer. A block is a
// sequence of steps. A call step is `call step.fn(context, step.pc, step.word)`, and the block
// returns at the first call that answers false. A run of native steps (NativeOp) is a segment:
// an inline guard first checks that the whole run may execute as native code, and the segment
// then runs inline, doing what CpuT::execute_at_pc() does for each instruction; when the guard
// refuses, the segment's steps run as calls instead. A load or store whose access the native
// code does not make itself (I/O, an exception, a debug break, an isolated cache) leaves the
// segment there for the same calls, from that instruction on.
// Xbyak stays inside the emitter's sources (emitter_impl.h).
#pragma once
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "core/cpu/decode.h"
#include "core/cpu/recompiler/block_links.h"
#include "core/types.h"

namespace psx {

// The instructions emitted as native code (cpu_execute.h gives their semantics).
enum class NativeOp : u8 {
  None,  // a call step
  Addiu, Slti, Sltiu, Andi, Ori, Xori, Lui,
  Sll, Srl, Sra, Sllv, Srlv, Srav, Addu, Subu, And, Or, Xor, Nor, Slt, Sltu,
  Mfhi, Mflo, Mthi, Mtlo,
  Mult, Multu, Div, Divu,  // block_emitter_muldiv.cpp
  // GTE moves and commands (block_emitter_cop2.cpp) and loads and stores (as the others), native
  // while SR.CU2 is set.
  Mfc2, Cfc2, Mtc2, Ctc2, Gte, Lwc2, Swc2,
  // Loads and stores: native for RAM and the scratchpad (block_emitter_memory.cpp).
  Lb, Lh, Lw, Lbu, Lhu, Lwl, Lwr, Sb, Sh, Sw, Swl, Swr,
  // Branches and jumps (never in a delay slot: the recompiler makes those call steps).
  Beq, Bne, Blez, Bgtz, J, Jal, Jr, Jalr, Bltz, Bgez, Bltzal, Bgezal,
};

// The bytes a load or store moves (the word of LWL/LWR/SWL/SWR; 1 for what is no memory access).
constexpr u32 access_width(NativeOp op) {
  switch (op) {
    case NativeOp::Lw: case NativeOp::Sw: case NativeOp::Lwc2: case NativeOp::Swc2: return 4;
    case NativeOp::Lh: case NativeOp::Lhu: case NativeOp::Sh: return 2;
    default: return 1;
  }
}

class BlockEmitter {
 public:
  using StepFn = bool (*)(void* context, u32 pc, u32 word);
  using BlockFn = void (*)();
  struct Step {
    u32 pc;
    u32 word;  // the instruction compiled
    StepFn fn;
    NativeOp native = NativeOp::None;
    // A native load's or store's I/O port (0: none): the address the recompiler guessed
    // (address_guess.h), where the native code calls the port's read or write itself
    // (Impl::io_access()).
    u32 io = 0;
  };
  // Where native code finds the machine's state: byte offsets of CpuT's fields from the context
  // plus `bias` (u32 unless noted), of the scheduler's time and deadline from `sched`, and the
  // interrupt controller's and the i-cache's tables. Native code holds context + bias, chosen so
  // that the fields it uses most lie within a signed byte of it (a one-byte displacement where
  // x86-64 would otherwise take four).
  struct Layout {
    void* context;
    int bias;
    void* sched;
    // load_val and new_load_val lie 4 bytes past load_reg and new_load_reg (each pair is tested
    // for zero as one 8-byte word).
    int regs, pc, next_pc, current_pc, load_reg, load_val, new_load_reg, new_load_val, shadow_reg;
    int loop_head, sr, cause, dcic, hook_pc, extra_hook_pc;
    // bool; hook_armed lies a byte past stop (both are tested for zero as one 2-byte word).
    int in_delay_slot, next_in_delay, stop, hook_armed;
    int hi, lo;
    int instructions, load_done_at, muldiv_ready_at, gte_ready_at;  // u64
    int idle_skip, hooks;                                // pointers
    int idle_last_head, idle_backoff;  // IdleSkip::backoff_cells(), from what idle_skip points to
    u32 no_loop_head;                  // CpuT::kNoLoopHead
    int now, deadline;                                   // u64, from sched
    int load_issue, load_bus;  // CpuT::kLoadIssue, kLoadBus (the load-shadow model)
    int ram_read;              // Bus::kRamRead (a RAM read outside that model: LWC2)
    const u32* irq_stat;
    const u32* irq_mask;
    const u32* icache_tags;    // ICache::tags()
    const u32* icache_words;   // ICache::words()
    // An i-cache miss in RAM filled natively (as Bus::icache_miss() and ICache::fill()): the
    // i-cache tags and words above, Bus::hot_lines_cell() (null: no native fills) and
    // no_hot_line(), and a word's fill time.
    u32* hot_lines;
    u32 no_hot_line;
    u32 fetch_word_cycles;     // Bus::kRamFetchUncached
    u32 icache_block_bits;     // Bus::icache_block_bits()
    const u32* cache_control;  // Bus::cache_control_cell()
    u32 icache_enable;         // Bus::icache_enable_bit()
    u8* ram;                  // Bus::ram(), 2 MiB, then the scratchpad's 1 KiB (Bus::scratchpad())
    const bool* dcache_mode;  // Bus::dcache_mode_cell()
    const void* watches;      // Bus::watches_cell(): a pointer, non-null while watches are attached
    const u64* code_bits;     // CodePages::bits(): which RAM words hold compiled code
    void* code_pages;         // the CodePages, and what a store to such a word calls
    void (*code_write)(void* code_pages, u32 ram_offset);
    u8* written_pages;  // Bus::written_pages(): a byte per page of ram, set by every store
    // The GTE and its register moves (Gte's member functions; the commands compile to
    // Gte::command_function()'s).
    void* gte;
    u32 (*gte_read_data)(void* gte, u32 r);
    u32 (*gte_read_control)(void* gte, u32 r);
    void (*gte_write_data)(void* gte, u32 r, u32 v);
    void (*gte_write_control)(void* gte, u32 r, u32 v);
    u32 (*gte_cycles)(u32 command);              // a command's cycles, known when compiling
    u32 gte_longest;                             // the most cycles of any command
    // Going on to the next block without the dispatcher (RecompilerT::run): CodePages::
    // any_dirty_cell() (mostly the byte after hook_armed, tested with it) and
    // BlockCache::recent_table() (kRecent entries).
    const bool* any_dirty;
    const void* recent_blocks;
    u32 recent_count;
    // An I/O load's or store's access for native code (RecompilerT::io_load(), io_store()), for
    // LB, LH, LW, LBU and LHU, and SB, SH and SW, in that order: the value loaded, with bit 32
    // set where the CPU may no longer run natively. A load's for each reach of its bus tail
    // (cpu_detail::kTailReaches, Impl::tail_plan()).
    u64 (*io_loads[5][cpu_detail::kTailReaches])(void* context, u32 address, u32 rt);
    u64 (*io_stores[3])(void* context, u32 address, u32 value);
  };

  // Whether a block may go on past its last two steps, a branch that may fall through (not `b` or
  // `bal`) and its delay slot: native code splits the branch there (Impl::splits_at()), its taken
  // way chaining to the target and its other way going on in the block. `shadow_reach`:
  // CpuT::kLoadIssue + kLoadBus - 1.
  static bool goes_on(std::span<const Step> steps, u32 shadow_reach);

  explicit BlockEmitter(size_t buffer_bytes);
  ~BlockEmitter();
  BlockEmitter(const BlockEmitter&) = delete;
  BlockEmitter& operator=(const BlockEmitter&) = delete;

  // The block's entry point, or nullptr when the buffer has no room left for it (clear() then
  // makes room; every block emitted before is gone).
  BlockFn emit(const Layout& layout, std::span<const Step> steps);
  void clear();
  size_t bytes_used() const;
  // What the last emit() that returned a block wrote: the block's code from its entry on (its
  // native runs, stubs and cold code, in one piece), and before that the fill routines where it
  // emitted them first (routines null otherwise); and its link sites (block_links.h), each
  // jumping to its next instruction until linked.
  struct Emitted {
    const void* routines = nullptr;
    size_t routine_bytes = 0;
    size_t block_bytes = 0;
    std::vector<BlockLinks::Site> links;
  };
  const Emitted& last_emitted() const { return last_; }

  struct Impl;  // the code generator (emitter_impl.h)

 private:
  std::unique_ptr<Impl> impl_;
  Emitted last_;
};

}  // namespace psx
