// The R3000A recompiler: runs CpuT::run()'s instructions from blocks of x86-64 code compiled on
// a block's first execution (block_emitter.h), kept in a cache by address and dropped when RAM
// holding them is written (block_cache.h, code_pages.h).
//
// Exact by construction: a block is the straight-line code from its first address up to and
// including a branch or jump and its delay slot (or kMaxBlock instructions), going on past a
// conditional branch that falls through where native code splits it (BlockEmitter::goes_on()), and
// each of its instructions is one step that does what one pass of the interpreter's run() loop
// does, minus the block lookup: the same deadline, stop and idle-loop checks, the BIOS hooks and
// interrupts through CpuT::step(), and the instruction itself through CpuT::execute_at_pc() (fetch
// through the i-cache model with its timing, the load shadow, execute, the load delay slot), or,
// when the i-cache holds the compiled word on a whole line (a fetch without time or fill), the same
// bookkeeping without fetch and decode (recompiler_ops.h). A step goes on to the next only while
// the CPU is where the block expects (pc + 4): an exception, an interrupt, a hook that redirects,
// or code changed since compilation so that a branch appears where none was, all leave the block
// for the dispatcher. Since each step fetches the word it executes, a stale block still runs what
// the interpreter would.
//
// The interpreter stays the reference (tests/unit/recompiler_test.cpp runs both and compares
// whole save states) and the fallback: where no code can be read, run() steps the interpreter.
#pragma once
#include <cstdint>
#include <cstdio>
#include <memory>
#include <ostream>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/cpu/cpu.h"
#include "core/cpu/idle_skip.h"
#include "core/cpu/recompiler/address_guess.h"
#include "core/cpu/recompiler/block_cache.h"
#include "core/cpu/recompiler/block_emitter.h"
#include "core/cpu/recompiler/code_pages.h"

namespace psx {

template <class BusT>
class RecompilerT {
 public:
  using Cpu = CpuT<BusT>;
  // A block's words lie in at most two code pages (BlockCache::insert() records its first and last).
  static constexpr u32 kMaxBlock = 64;
  static_assert(kMaxBlock * 4 <= 1u << CodePages::kPageBits);
  // Tumble in play compiles to about 1500 blocks of 4.3 KB on average (slow paths included): a
  // 4 MiB buffer filled and was dropped every ~120 moves. Pages become resident only once
  // written, so a console holds what it compiled, not the whole buffer.
  static constexpr size_t kCodeBytes = 16 << 20;

  struct Stats {
    u64 compiled = 0;      // blocks compiled
    u64 invalidated = 0;   // times written pages' blocks were dropped
    u64 flushes = 0;       // times the code buffer filled up and every block was dropped
  };

  // BusT provides peek_code(vaddr, word): the word a fetch would execute, false where none.
  explicit RecompilerT(BusT& bus) : bus_(bus) {}

  // CpuT::run() with the recompiler attached.
  void run(Cpu& cpu);
  // The page map the bus reports RAM writes to.
  CodePages& code_pages() { return pages_; }
  const Stats& stats() const { return stats_; }
  size_t blocks() const { return cache_.size(); }
  size_t link_sites() const { return cache_.link_sites(); }
  // Bytes of the code buffer in use (what a console holds of it).
  size_t code_bytes() const { return emitter_ ? emitter_->bytes_used() : 0; }
  // Where compile() names the host code it writes, for profilers of the compiled code: a line per
  // block, "<start> <size> psx_block_<pc>" (hex, no prefix, the pc as 8 digits), and one
  // "psx_fill_routines" line where a block's emission wrote the i-cache fill routines first: the
  // map Linux perf reads from /tmp/perf-<pid>.map. Null (the default): nowhere. A map attached
  // where code was compiled before drops that code (drop_all()): what runs from then on is
  // compiled again, the fill routines first, and named (an environment boots its game before a
  // profiler can attach the map).
  void set_code_map(std::ostream* out) {
    if (out && out != code_map_ && code_bytes() > 0) drop_all();
    code_map_ = out;
  }
  // Drops every compiled block and the record of their code, as when the code buffer fills up:
  // what a block was compiled from may have been written unseen (while the bus reported RAM
  // writes to no code pages, the interpreter running).
  void drop_all() {
    cache_.clear();
    pages_.clear();
    recheck_icache_lines();
    if (emitter_) emitter_->clear();
  }

 private:
  BlockEmitter::BlockFn compile(Cpu& cpu, u32 pc);
  void step_resumed(Cpu& cpu);
  // The console's bus keeps i-cache lines stale where blocks were dropped (ICache::kStale); other
  // buses have no i-cache and no native code.
  bool memory_holds(u32 vaddr, u32 word) const {
    if constexpr (std::is_same_v<BusT, Bus>) return bus_.memory_holds(vaddr, word);
    else return true;
  }
  void recheck_icache_lines() {
    if constexpr (std::is_same_v<BusT, Bus>) bus_.recheck_icache_lines();
  }
  static bool ends_block(u32 instr);
  // The steps (recompiler_ops.h).
  static BlockEmitter::StepFn step_for(u32 word);
  static NativeOp native_for(u32 word);
  BlockEmitter::Layout layout(Cpu& cpu);
  static NativeOp decode_op(u32 instr);
  [[gnu::always_inline]] static bool may_step(Cpu& c, u32 pc);
  static bool step_at(void* cpu, u32 pc, u32 word);
  template <NativeOp K>
  static bool step_fast(void* cpu, u32 pc, u32 word);
  template <NativeOp K>
  static void exec(Cpu& c, u32 instr);
  template <NativeOp K>
  static void store_call(Cpu& c, u32 instr);
  template <NativeOp K>
  static void load_call(Cpu& c, u32 instr);
  template <NativeOp K>
  static u32 port_read(Cpu& c, u32 address, u32 rt, u32 reach = cpu_detail::kTailUnknown);
  template <NativeOp K>
  static bool port_write(Cpu& c, u32 address, u32 value);
  template <NativeOp K, u32 Reach>
  static u64 io_load(void* context, u32 address, u32 rt);
  template <NativeOp K, u32... Reach>
  static void set_io_loads(BlockEmitter::Layout& l, std::integer_sequence<u32, Reach...>);
  template <NativeOp K>
  static u64 io_store(void* context, u32 address, u32 value);
  static bool leaves_native(const Cpu& c) { return c.stop_ || c.hook_armed_ || c.interrupt_pending(); }

  BusT& bus_;
  CodePages pages_;
  BlockCache cache_;
  std::unique_ptr<BlockEmitter> emitter_;  // made on first use: consoles that never recompile
                                           // allocate no code buffer
  void map_code(BlockEmitter::BlockFn fn, u32 pc) const;

  Stats stats_;
  std::vector<BlockEmitter::Step> steps_;
  std::ostream* code_map_ = nullptr;
};

template <class BusT>
void RecompilerT<BusT>::run(Cpu& cpu) {
  cpu.stop_ = false;
  cpu.resume_pc_ = cpu.pc_;
  while (!cpu.stop_ && cpu.sched_.now() < cpu.sched_.next_deadline()) {
    if constexpr (std::is_same_v<BusT, Bus>) {  // as CpuT::run()
      if (cpu.at_loop_head()) {
        cpu.loop_head_ = Cpu::kNoLoopHead;
        cpu.idle_skip_->at_loop_head(cpu);
        continue;
      }
    }
    if (pages_.any_dirty()) {
      for (u32 page : pages_.take_dirty()) cache_.invalidate_page(page);
      recheck_icache_lines();
      ++stats_.invalidated;
    }
    BlockEmitter::BlockFn block = cache_.find(cpu.pc_);
    if (!block && cpu.pc_ == cpu.resume_pc_ && pages_.compiled(cpu.pc_)) {
      step_resumed(cpu);
      continue;
    }
    if (!block) block = compile(cpu, cpu.pc_);
    if (block) block();
    else cpu.step();
  }
}

// The CPU takes up the program inside a compiled block (Cpu::resume_pc_): the deadline stops a
// block at any instruction, and an interrupt returns to wherever it was taken, so compiling a
// block from there would, over a long run, compile a block from nearly every instruction of the
// program's busy code. Those instructions are interpreted instead, one a pass, until a branch's
// delay slot has run; its target (or its fall-through) mostly starts a block, or else is worth
// compiling.
template <class BusT>
void RecompilerT<BusT>::step_resumed(Cpu& cpu) {
  cpu.step();
  cpu.resume_pc_ = cpu.in_delay_slot_ ? Cpu::kNoResume : cpu.pc_;
}

template <class BusT>
bool RecompilerT<BusT>::ends_block(u32 instr) {
  const u32 op = instr >> 26;
  if (op >= 0x01 && op <= 0x07) return true;  // BcondZ, J, JAL, BEQ, BNE, BLEZ, BGTZ
  if (op != 0) return false;
  const u32 funct = instr & 63;
  return funct == 0x08 || funct == 0x09;  // JR, JALR
}

template <class BusT>
BlockEmitter::BlockFn RecompilerT<BusT>::compile(Cpu& cpu, u32 pc) {
  steps_.clear();
  u32 a = pc, word;
  bool delay_slot = false;
  AddressGuess guess(cpu.regs_);
  while (steps_.size() < kMaxBlock && bus_.peek_code(a, word)) {
    // A branch in a delay slot (jumping from where the first one went) stays a call step, and
    // so does a load or store that will likely find I/O.
    // Native code runs only words that memory still holds (an i-cache line still holding older
    // code runs it through calls), since it checks a line by its tag alone (ICache::kStale).
    NativeOp native = native_for(word);
    u32 io = 0;
    const bool branch_in_slot = delay_slot && ends_block(word);
    if (branch_in_slot || !memory_holds(a, word)) {
      native = NativeOp::None;
    } else if (native != NativeOp::None && guess.elsewhere(word)) {
      io = delay_slot ? 0 : guess.io_port(word, native);  // not where a split branch's flag lives (r8)
      if (io == 0) native = NativeOp::None;
    }
    guess.after(word);
    steps_.push_back({a, word, step_for(word), native, io});
    if (delay_slot && !BlockEmitter::goes_on(steps_, u32(Cpu::kLoadIssue + Cpu::kLoadBus - 1))) break;
    delay_slot = ends_block(word);  // a delay slot that goes on is no branch (goes_on())
    a += 4;
  }
  if (steps_.empty()) return nullptr;  // no code there: the interpreter raises the bus error
  // A native I/O access checks the machine after its call for the instructions after it
  // (Impl::io_checks()); as the block's last it would leave that to the chain, which does not.
  if (steps_.back().io != 0) steps_.back().native = NativeOp::None, steps_.back().io = 0;
  if (!emitter_) emitter_ = std::make_unique<BlockEmitter>(kCodeBytes);
  const BlockEmitter::Layout lay = layout(cpu);
  BlockEmitter::BlockFn fn = emitter_->emit(lay, steps_);
  if (!fn) {
    ++stats_.flushes;
    drop_all();
    fn = emitter_->emit(lay, steps_);
  }
  if (code_map_) map_code(fn, pc);
  const u32 first = CodePages::page_of(pc), last = CodePages::page_of(steps_.back().pc);
  if (first != CodePages::kNoPage && last != CodePages::kNoPage) pages_.mark_compiled(pc, steps_.back().pc);
  cache_.insert(pc, fn, first, last, emitter_->last_emitted().links);
  ++stats_.compiled;
  return fn;
}

template <class BusT>
void RecompilerT<BusT>::map_code(BlockEmitter::BlockFn fn, u32 pc) const {
  const BlockEmitter::Emitted& e = emitter_->last_emitted();
  char line[64];
  if (e.routines) {
    const int n = std::snprintf(line, sizeof line, "%llx %zx psx_fill_routines\n",
                                static_cast<unsigned long long>(reinterpret_cast<uintptr_t>(e.routines)), e.routine_bytes);
    code_map_->write(line, n);
  }
  const int n = std::snprintf(line, sizeof line, "%llx %zx psx_block_%08x\n",
                              static_cast<unsigned long long>(reinterpret_cast<uintptr_t>(fn)), e.block_bytes, pc);
  code_map_->write(line, n);
}

using Recompiler = RecompilerT<Bus>;

}  // namespace psx

#include "core/cpu/recompiler/recompiler_ops.h"
