// Idle-loop skipping: recording one iteration, proving the next ones repeat it, skipping them.
#include "core/cpu/idle_skip.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <type_traits>

#include "core/bus.h"
#include "core/cpu/cpu.h"
#include "core/cpu/idle_proof.h"
#include "core/endian.h"
#include "spu/spu.h"

namespace psx {

// The CPU's members are instantiated once, in cpu.cpp.
extern template class CpuT<Bus>;

namespace {

constexpr u32 kSpustat = 0x1F801DAE;

// I/O registers whose read changes nothing and whose value changes only when an event runs or
// the CPU writes somewhere (psx-spx register descriptions; the devices' io_read confirm it):
// memory control, RAM_SIZE, I_STAT/I_MASK, every DMA register, the CD-ROM status and interrupt
// enable/flag registers (not the response or data FIFOs), SPUCNT and SPUSTAT (bit 11 with the
// SPU's batches ending at its flips, Spu::end_batches_at_flips); of GPUSTAT bits
// 0-30, bit 31 being the line parity, which changes at every scanline while the line is counted
// between events (gpu/video_timing.h); of JOY_STAT (pad/card port status) bits 0-10, bits 11-31
// being its baud timer, which counts between events. Returns those bits of the 32-bit word at
// p & ~3, or 0 for registers with none: timer counters (they count), FIFOs, GPUREAD, JOY_DATA (a
// read pops).
u32 pure_io_bits(u32 p, u32 width) {
  if (p >= 0x1F801000 && p < 0x1F801024) return ~0u;
  if (p >= 0x1F801060 && p < 0x1F801064) return ~0u;
  if (p >= 0x1F801070 && p < 0x1F801078) return ~0u;
  if (p >= 0x1F801080 && p < 0x1F801100) return ~0u;
  if (p == 0x1F801800 || p == 0x1F801803) return ~0u;
  if (p >= 0x1F801814 && p < 0x1F801818) return 0x7FFFFFFF;
  if ((p == 0x1F801DAA || p == kSpustat) && width <= 2) return ~0u;
  if (p >= 0x1F801044 && p < 0x1F801048) return 0x7FF;
  return 0;
}

// A load the loop may make: no exception, no side effect. Returns which bits of the value it
// delivers (after sign or zero extension) cannot change before the next event; 0 = none, refused.
u32 pure_load_bits(u32 sr, u32 vaddr, u32 width, bool sign) {
  if (vaddr & (width - 1)) return 0;
  if ((sr & Cop0::kKUc) && (vaddr & 0x80000000)) return 0;
  if (vaddr >= 0xC0000000) return 0;
  const u32 p = Bus::physical(vaddr);
  if (p < 0x00800000) return ~0u;
  if (p >= 0x1F800000 && p < 0x1F800000 + Bus::kScratchSize) return vaddr < 0xA0000000 ? ~0u : 0;
  if (p >= 0x1FC00000 && p < 0x1FC00000 + Bus::kBiosSize) return ~0u;
  u32 bits = pure_io_bits(p, width);
  if (bits == ~0u || bits == 0 || width == 4) return bits;
  // The bytes read, at the bottom of the value; the extension is known when its source bit is.
  const u32 value_mask = (1u << (8 * width)) - 1, sign_bit = 1u << (8 * width - 1);
  bits = (bits >> (8 * (p & 3))) & value_mask;
  if (!sign || (bits & sign_bit)) bits |= ~value_mask;
  return bits;
}

// Cycles until a shadowed load's access ends at `done`, seen at time `now` (cpu.h): 0 when
// nothing can wait for it any more.
Cycles shadow_left(Cycles done, Cycles now) { return done > now ? done - now : 0; }

// What names a word of RAM or the scratchpad whichever mirror or segment addresses it: RAM's
// offset, or the scratchpad's with bit 31 set; kNoWord elsewhere (I/O, the BIOS ROM).
constexpr u32 kNoWord = ~0u, kScratchTag = 0x80000000;
u32 location(u32 vaddr) {
  const u32 p = Bus::physical(vaddr);
  if (p < 0x00800000) return p & (Bus::kRamSize - 1);
  if (p >= 0x1F800000 && p < 0x1F800000 + Bus::kScratchSize && vaddr < 0xA0000000)
    return kScratchTag | (p & (Bus::kScratchSize - 1));
  return kNoWord;
}

u32 word_at(Bus& bus, u32 loc) {
  return load_le32(loc & kScratchTag ? bus.scratchpad() + (loc & ~kScratchTag) : bus.ram() + loc);
}

// The proof knows of a load's value only the bits pure_load_bits() gave (IdleProof's partial
// values): JOY_STAT's baud timer, say, may read otherwise.
bool same_step(const IdleStep& a, const IdleStep& b) {
  return a.pc == b.pc && a.instr == b.instr && a.addr == b.addr && a.load_bits == b.load_bits &&
         ((a.load_value ^ b.load_value) & a.load_bits) == 0;
}

// The general registers an instruction names (bit r for register r): rs, rt and rd of SPECIAL,
// rs and r31 of BcondZ, r31 of JAL, rs and rt of the rest (more than some use, which is safe).
u32 named_registers(u32 instr) {
  const u32 op = instr >> 26, rs = 1u << ((instr >> 21) & 31), rt = 1u << ((instr >> 16) & 31);
  switch (op) {
    case 0x00: return rs | rt | 1u << ((instr >> 11) & 31);
    case 0x01: return rs | 1u << 31;
    case 0x02: return 0;
    case 0x03: return 1u << 31;
    default: return rs | rt;
  }
}

bool load_signed(u32 instr) { return (instr >> 26) == 0x20 || (instr >> 26) == 0x21; }  // LB, LH

u32 load_width(u32 instr) {
  switch (instr >> 26) {
    case 0x20: case 0x24: return 1;  // LB, LBU
    case 0x21: case 0x25: return 2;  // LH, LHU
    case 0x23: return 4;             // LW
    default: return 0;
  }
}

}  // namespace

IdleSkip::BackoffCells IdleSkip::backoff_cells() {
  static_assert(std::is_standard_layout_v<IdleSkip> && sizeof(Backoff) == kBackoffBytes &&
                offsetof(Backoff, head) == 0 && offsetof(Backoff, visits) == kBackoffVisits);
  return {int(offsetof(IdleSkip, last_head_)), int(offsetof(IdleSkip, backoff_))};
}

// Nothing that would have the iteration leave the plain path: a delay slot, a hook about to run,
// D-cache mode, an interrupt to take, a debug break on code or data.
bool IdleSkip::may_skip_here(const Cpu& cpu) {
  return !cpu.next_in_delay_ && !cpu.hook_armed_ && !cpu.bus_.dcache_mode() && !cpu.interrupt_pending() &&
         !(cpu.cop0_.dcic & (Cop0::kDcicPCE | Cop0::kDcicDAE));
}

IdleSkip::Pipeline IdleSkip::pipeline(const Cpu& cpu) {
  return {cpu.load_reg_, cpu.load_val_, cpu.new_load_reg_, cpu.new_load_val_};
}

void IdleSkip::at_loop_head(Cpu& cpu) {
  const u32 head = cpu.pc_;
  Backoff& b = backoff_[(head >> 2) % backoff_.size()];
  if (head == last_head_ && cpu.sched_.now() + last_cost_ >= cpu.sched_.next_deadline()) {
    // Right after a skip: the next event falls due within this iteration, which is interpreted.
  } else if (b.head == head && b.visits > 0) {
    --b.visits;
  } else {
    if (b.head != head) b = Backoff{head, 0, 0, 0};
    ++stats_.examinations;
    Examined e = repeat(cpu);
    if (e == Examined::refused) {
      // No proof made here covers this iteration, which most often leaves the loop (the status
      // bit it waited for is set): an examination would interpret the way out until something
      // disqualifies it. Where the last ones here all were refused, only the 1st, 2nd, 4th, 8th...
      // such visit is examined (one may also find a second way round the loop, which is then
      // proven and repeated).
      const bool proven_here =
          std::any_of(proven_.begin(), proven_.end(), [head](const Proven& p) { return p.head == head; });
      if (!proven_here || std::has_single_bit(++b.leaving)) {
        e = examine(cpu);
        if (e != Examined::refused) b.leaving = 0;
      } else {
        ++stats_.unexamined;
      }
    }
    if (e != Examined::refused) {
      b.failures = 0;
      // The recorded iteration's back branch left the loop head set, so the head is met again
      // at once, at the iteration after the skip. Where the proof's bound ended the skip, that
      // is one the proof could not show to repeat, most often the loop's last: examining it
      // would only record the loop's exit and the code after it until something disqualifies
      // (Tumble's pad delays ran 23 and 47 instructions so every frame). It runs as usual.
      b.visits = e == Examined::skipped_to_bound ? 1 : 0;
    } else {
      b.failures = std::min<u32>(b.failures + 1, kMaxBackoff);
      b.visits = (1u << b.failures) - 1;
    }
  }
  // Nothing done (backing off, or an event due within the iteration): the run loop, which has
  // cleared the loop head, goes on from the head as usual (the recompiler with the head's block).
}

IdleSkip::Examined IdleSkip::examine(Cpu& cpu) {
  Bus& bus = cpu.bus_;
  Scheduler& sched = cpu.sched_;
  const u32 head = cpu.pc_;
  if (!may_skip_here(cpu)) return Examined::refused;

  // 1. Execute one iteration, vetting each instruction before it runs.
  const Cycles deadline = sched.next_deadline();
  const Cycles t0 = sched.now();
  const u64 i0 = cpu.instructions_;
  const std::array<u32, 32> regs0 = cpu.regs_;
  const Pipeline load0 = pipeline(cpu);
  const Cycles done0 = cpu.load_done_at_;
  const u32 shadow_reg0 = cpu.shadow_reg_;
  const ICache& icache = bus.icache();
  path_len_ = 0;
  cells_.count = 0;
  do {
    if (cpu.stop_ || sched.now() >= deadline) return Examined::refused;
    if (path_len_ == kMaxPath) return Examined::refused;
    u32 instr;
    if (!bus.peek_code(cpu.pc_, instr)) return Examined::refused;  // the word the fetch will execute
    IdleStep& st = path_[path_len_++];
    st = {cpu.pc_, instr, 0, 0, 0};
    tags_[path_len_ - 1] = icache.tag(ICache::line(cpu.pc_));
    const IdleProof::Kind kind = IdleProof::classify(instr);
    if (kind == IdleProof::Kind::Other) return Examined::refused;
    if (kind == IdleProof::Kind::Branch && cpu.next_in_delay_) return Examined::refused;
    const u32 width = load_width(instr);
    if (width || kind == IdleProof::Kind::Store)
      st.addr = cpu.regs_[(instr >> 21) & 31] + static_cast<u32>(static_cast<s16>(instr & 0xFFFF));
    if (width) {
      st.load_bits = pure_load_bits(cpu.cop0_.sr, st.addr, width, load_signed(instr));
      if (st.load_bits == 0) return Examined::refused;
      // The first SPUSTAT poll makes the SPU end its batches at bit 11's flips, which may bring
      // its event before the deadline this examination started with: examined again next time.
      if (Bus::physical(st.addr) == kSpustat && spu_ && spu_->end_batches_at_flips()) return Examined::refused;
    }
    if (kind == IdleProof::Kind::Store && !note_store(cpu, st)) return Examined::refused;
    cpu.step();
    st.load_value = cpu.load_val_;
    if (cpu.hook_armed_) return Examined::refused;
  } while (cpu.pc_ != head || cpu.next_in_delay_);

  // The iteration ran without an event falling due (events only run at or after the deadline),
  // filled no i-cache line (a fill changes its line's tag, and a later fill in the same iteration
  // cannot restore it: both would be for addresses the iteration fetches, with one tag), and left
  // the load pipeline as it was.
  const Cycles t1 = sched.now();
  if (t1 >= deadline) return Examined::refused;
  for (u32 i = 0; i < path_len_; ++i)
    if (icache.tag(ICache::line(path_[i].pc)) != tags_[i]) return Examined::refused;
  if (pipeline(cpu) != load0) return Examined::refused;
  // A load in flight shapes the iteration's timing (cpu.h, load shadow): it must be in flight
  // for as long, into the same register, at the end as at the start.
  const Cycles shadow0 = shadow_left(done0, t0), shadow1 = shadow_left(cpu.load_done_at_, t1);
  if (shadow0 != shadow1 || (shadow0 && shadow_reg0 != cpu.shadow_reg_)) return Examined::refused;
  if (!name_cells(bus)) return Examined::refused;

  // 2. Prove the following iterations repeat it, each adding the same step to the registers (and
  // to the words it stores to).
  u64 max_k;
  if (cells_.count > 0 || !reuse_proof(regs0, cpu.regs_, cpu.load_reg_, cpu.load_val_, max_k)) {
    IdleProof proof(regs0, cpu.regs_, cpu.load_reg_, cpu.load_val_, cells_);
    if (!proof.run(path_.data(), path_len_)) return Examined::refused;
    max_k = proof.max_k();
    ++stats_.proofs;
    Proven* p = &proven_[proven_next_++ % kProofs];
    p->reproof.valid = false;
    p->head = head;
    p->len = path_len_;
    std::copy(path_.begin(), path_.begin() + path_len_, p->path.begin());
    p->before = regs0;
    p->line = RegisterLine(regs0, cpu.regs_);
    p->load_reg = cpu.load_reg_;
    p->load_val = cpu.load_val_;
    p->max_k = max_k;
    note_context(cpu, *p, shadow0, shadow_reg0, t0, done0, cpu.instructions_ - i0);
  }

  // 3. Skip whole iterations, ending before the deadline so the event's iteration is interpreted.
  const Cycles cost = t1 - t0;
  const u64 steps = cpu.instructions_ - i0;
  const u64 by_time = (deadline - 1 - t1) / cost;
  const u64 n = max_k < by_time ? max_k + 1 : by_time;
  last_head_ = head;
  last_cost_ = cost;
  if (n == 0) return Examined::refused;
  for (u32 i = 1; i < 32; ++i) cpu.regs_[i] += static_cast<u32>(n) * (cpu.regs_[i] - regs0[i]);
  // As the last skipped iteration's store leaves it (through the bus: a word of compiled code
  // drops its blocks).
  for (u32 c = 0; c < cells_.count; ++c)
    bus.write32(cells_.vaddr[c], cells_.after[c] + static_cast<u32>(n) * (cells_.after[c] - cells_.before[c]));
  if (cpu.load_done_at_ != done0) cpu.load_done_at_ += n * cost;  // each iteration's load, as the last
  sched.advance(n * cost);
  cpu.instructions_ += n * steps;
  ++stats_.skips;
  stats_.iterations += n;
  stats_.cycles += n * cost;
  return max_k < by_time ? Examined::skipped_to_bound : Examined::skipped_to_event;
}

// What repeat() needs of the proof just made, recorded from t0 to now with `steps` instructions;
// examine() has checked that the iteration left the pipeline and the load shadow as it found
// them, and it ran no instruction that changes SR or the cache or memory control registers.
void IdleSkip::note_context(Cpu& cpu, Proven& p, Cycles shadow0, u32 shadow_reg0, Cycles t0, Cycles done0,
                            u64 steps) const {
  Bus& bus = cpu.bus_;
  p.at.pipeline = pipeline(cpu);
  p.at.sr = cpu.cop0_.sr;
  p.at.cache_control = *bus.cache_control_cell();
  p.at.memory_control = bus.memory_control();
  p.at.shadow = shadow0;
  p.at.shadow_reg = shadow_reg0;
  Proven::Checks& c = p.checks;
  c.lines = c.jumps = c.loads = 0;
  for (u32 i = 0; i < path_len_; ++i) {
    const IdleStep& st = path_[i];
    const u32 line = ICache::line(st.pc);
    if (std::find(c.line.begin(), c.line.begin() + c.lines, line) == c.line.begin() + c.lines)
      c.line[c.lines] = line, c.tag[c.lines++] = tags_[i];
    c.fetched[i] = bus.cached_code(st.pc) ? static_cast<u16>((st.pc >> 2) & (ICache::kLines * 4 - 1))
                                          : Proven::Checks::kFetchedElsewhere;
    const u32 next = i + 1 < path_len_ ? path_[i + 1].pc : p.head;
    if (next != st.pc + 4) c.jump_target[c.jumps++] = next;
    if (load_width(st.instr) != 0 && st.cell == 0) c.load_step[c.loads++] = static_cast<u8>(i);
  }
  p.cells = cells_;
  p.named = 1;
  for (u32 i = 0; i < path_len_; ++i) p.named |= named_registers(path_[i].instr);
  p.cost = cpu.sched_.now() - t0;
  p.steps = steps;
  p.current_pc = cpu.current_pc_;
  p.in_delay_slot = cpu.in_delay_slot_;
  p.shadow_reg = cpu.shadow_reg_;
  p.load_done_moved = cpu.load_done_at_ != done0;
  p.load_done = cpu.load_done_at_ - t0;
}

// An iteration about to start at the head where everything that routed and timed a proven
// iteration is as it was and every load reads what it read (the bits the proof knew) follows the
// same path in the same cycles if its registers lead it there. When they lie on the proof's line
// within its bound (j iterations on from the recorded start, 1 <= j <= max_k + 1), it is the
// proof's iteration j - 1; otherwise (the loop entered again from an earlier spin count, say) the
// same path is proven again from here, which shows it as well, and the proof is kept from here.
// The iterations it covers are then skipped as examine() skips them, up to the next event.
IdleSkip::Examined IdleSkip::repeat(Cpu& cpu) {
  if (cpu.stop_ || !may_skip_here(cpu)) return Examined::refused;
  for (Proven& p : proven_) {
    u64 n;
    if (p.head != cpu.pc_ || !repeats(cpu, p, n)) continue;
    const Cycles now = cpu.sched_.now();
    p.line.advance(cpu.regs_, static_cast<u32>(n));
    cpu.current_pc_ = p.current_pc;
    cpu.in_delay_slot_ = p.in_delay_slot;
    cpu.shadow_reg_ = p.shadow_reg;
    if (p.load_done_moved) cpu.load_done_at_ = now + (n - 1) * p.cost + p.load_done;
    cpu.sched_.advance(n * p.cost);
    cpu.instructions_ += n * p.steps;
    for (u32 c = 0; c < p.cells.count; ++c) {  // as the last iteration's store leaves it
      const u32 now_value = word_at(cpu.bus_, p.cells.location[c]);
      cpu.bus_.write32(p.cells.vaddr[c], now_value + static_cast<u32>(n) * (p.cells.after[c] - p.cells.before[c]));
    }
    last_head_ = p.head;
    last_cost_ = p.cost;
    ++stats_.skips;
    ++stats_.repeats;
    stats_.iterations += n;
    stats_.cycles += n * p.cost;
    return Examined::repeated;
  }
  return Examined::refused;
}

// Whether the iteration about to start is one p proves (repeat()); n: how many iterations from
// it on to skip.
bool IdleSkip::repeats(Cpu& cpu, Proven& p, u64& n) {
  Bus& bus = cpu.bus_;
  const Cycles now = cpu.sched_.now(), deadline = cpu.sched_.next_deadline();
  if (now >= deadline) return false;
  // The loads first: where the loop is about to leave (the status bit it waited for came with the
  // event that ended the last skip), a load's value is what differs, and the checks below would
  // all pass first.
  const Proven::Checks& c = p.checks;
  for (u32 l = 0; l < c.loads; ++l) {
    const IdleStep& st = p.path[c.load_step[l]];
    const u32 width = load_width(st.instr);
    u32 v;
    if (!bus.peek_data(st.addr, width, v)) return false;
    if (load_signed(st.instr)) v = width == 2 ? u32(s32(s16(v))) : u32(s32(s8(v)));  // as CpuT::load
    if ((v ^ st.load_value) & st.load_bits) return false;
  }
  if ((p.cells.count > 0 && *bus.watches_cell() != nullptr) ||
      pipeline(cpu) != p.at.pipeline || cpu.cop0_.sr != p.at.sr || *bus.cache_control_cell() != p.at.cache_control ||
      bus.memory_control() != p.at.memory_control ||
      shadow_left(cpu.load_done_at_, now) != p.at.shadow || cpu.shadow_reg_ != p.at.shadow_reg)
    return false;
  const ICache& icache = bus.icache();
  for (u32 l = 0; l < c.lines; ++l)
    if (icache.tag(c.line[l]) != c.tag[l]) return false;
  const u32* cached = icache.words();
  for (u32 i = 0; i < p.len; ++i) {
    u32 word;
    if (c.fetched[i] != Proven::Checks::kFetchedElsewhere) word = cached[c.fetched[i]];
    else if (!bus.peek_code(p.path[i].pc, word)) return false;
    if (word != p.path[i].instr) return false;
  }
  for (u32 j = 0; j < c.jumps; ++j)
    if (cpu.hooked(c.jump_target[j])) return false;
  u64 covered;  // iterations from this one on that a proof covers (~0: no end)
  u32 j;
  if (!p.line.iterations(p.before, cpu.regs_, j, ~p.named)) return false;
  if (j == 0 && p.line.still()) j = 1;  // then every iteration starts as the recorded one did
  if (p.cells.count == 0 && j >= 1 && (p.max_k == ~u64{0} || j <= p.max_k + 1)) {
    covered = p.max_k == ~u64{0} ? p.max_k : p.max_k + 2 - j;
  } else {
    std::array<u32, 32> before = cpu.regs_;
    p.line.advance(before, ~0u);  // one step back
    IdleCells cells = p.cells;  // the stored words now, and a step back
    for (u32 c = 0; c < cells.count; ++c) {
      cells.after[c] = word_at(bus, cells.location[c]);
      cells.before[c] = cells.after[c] - (p.cells.after[c] - p.cells.before[c]);
    }
    Proven::Reproof& r = p.reproof;
    if (!same_start(r, cpu, cells, p.named)) {
      IdleProof proof(before, cpu.regs_, cpu.load_reg_, cpu.load_val_, cells);
      r.repeats = proof.run(p.path.data(), p.len);
      r.max_k = proof.max_k();
      r.regs = cpu.regs_;
      r.load_reg = cpu.load_reg_;
      r.load_val = cpu.load_val_;
      for (u32 c = 0; c < cells.count; ++c) r.words[c] = cells.after[c];
      r.valid = true;
    }
    if (!r.repeats) return false;
    covered = r.max_k == ~u64{0} ? r.max_k : r.max_k + 1;
    if (cells.count == 0) {  // the proof now starts here, for the loop's next entry from here
      p.before = before;
      p.max_k = r.max_k;
    }
  }
  // Whole iterations that end before the next event.
  n = std::min<u64>(covered, (deadline - 1 - now) / p.cost);
  return n > 0;
}

// Whether the proof last made again from p's head (Proven::Reproof) started from the registers,
// the load in flight and the stored words' values there are now: it is then the same proof. A
// register no instruction of the path names (`named`) is neither read nor written by it and plays
// no part in the proof (as in reuse_proof()), so it may differ.
bool IdleSkip::same_start(const Proven::Reproof& r, const Cpu& cpu, const IdleCells& cells, u32 named) {
  if (!r.valid || r.load_reg != cpu.load_reg_ || r.load_val != cpu.load_val_) return false;
  for (u32 m = named; m != 0; m &= m - 1) {
    const u32 reg = static_cast<u32>(std::countr_zero(m));
    if (r.regs[reg] != cpu.regs_[reg]) return false;
  }
  for (u32 c = 0; c < cells.count; ++c)
    if (r.words[c] != cells.after[c]) return false;
  return true;
}

// A store the loop may make (before it runs): a word to RAM or the scratchpad that reaches memory
// and nothing else (kernel mode or a KUSEG address, no isolated cache, no memory watch to see it),
// into at most IdleCells::kMax words. The word's value before the iteration is noted.
bool IdleSkip::note_store(Cpu& cpu, IdleStep& st) {
  Bus& bus = cpu.bus_;
  const u32 loc = location(st.addr);
  if (loc == kNoWord || pure_load_bits(cpu.cop0_.sr, st.addr, 4, false) == 0 || (cpu.cop0_.sr & Cop0::kIsC) ||
      *bus.watches_cell() != nullptr)
    return false;
  int c = cells_.find(loc);
  if (c < 0) {
    if (cells_.count == IdleCells::kMax) return false;
    c = static_cast<int>(cells_.count++);
    cells_.location[c] = loc;
    cells_.vaddr[c] = st.addr;
    cells_.before[c] = word_at(bus, loc);
  }
  st.cell = static_cast<u32>(c) + 1;
  return true;
}

// After the iteration: each load of a stored word names its cell, and the cells their values
// now. A load of part of a stored word, or code fetched from one, is not followed.
bool IdleSkip::name_cells(Bus& bus) {
  if (cells_.count == 0) return true;
  const auto cell_of = [this](u32 vaddr) {
    const u32 loc = location(vaddr);
    return loc == kNoWord ? -1 : cells_.find(loc & ~3u);
  };
  for (u32 i = 0; i < path_len_; ++i) {
    IdleStep& st = path_[i];
    if (cell_of(st.pc) >= 0) return false;
    const u32 width = load_width(st.instr);
    if (width == 0) continue;
    const int c = cell_of(st.addr);
    if (c < 0) continue;
    if (width != 4) return false;
    st.cell = static_cast<u32>(c) + 1;
  }
  for (u32 c = 0; c < cells_.count; ++c) cells_.after[c] = word_at(bus, cells_.location[c]);
  return true;
}

// The proof covers iterations k = 0..max_k after its recorded one, each starting from
// before + (k+1)*step. An iteration recorded now that repeats the proven one step for step (the
// same instructions, load addresses and values, hence the same decisions), adds the same step and
// leaves the same load in flight, from before + j*step, is the proven iteration j - 1 or the
// recorded one itself (j = 0); the iterations after it are the proven ones from j on. A register
// no instruction of the path names plays no part in the proof, so the loop met again with another
// value there (a transfer's byte count, say) is still the proven one. A loop can have several
// proofs (JOY_STAT's /ACK bit read high in one transfer, low in the next).
bool IdleSkip::reuse_proof(const std::array<u32, 32>& before, const std::array<u32, 32>& after, u32 load_reg,
                           u32 load_val, u64& max_k) const {
  for (const Proven& p : proven_) {
    if (p.head != path_[0].pc || p.len != path_len_ || p.load_reg != load_reg || p.load_val != load_val) continue;
    if (!std::equal(path_.begin(), path_.begin() + path_len_, p.path.begin(), same_step)) continue;
    u32 j;
    if (!p.line.same_steps(before, after) || !p.line.iterations(p.before, before, j, ~p.named) || j > p.max_k) continue;
    max_k = p.max_k == ~u64{0} ? p.max_k : p.max_k - j;
    return true;
  }
  return false;
}

}  // namespace psx
