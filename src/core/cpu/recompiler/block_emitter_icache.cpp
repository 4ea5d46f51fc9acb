// The i-cache side of compiled blocks (emitter_impl.h): the line checks that let native code
// run only from i-cache hits still holding the compiled words, and the fills native code makes
// itself on a miss in RAM, as Bus::fetch_slow() and ICache::fill() make them.
#include <stdexcept>

#include "core/bus.h"
#include "core/cpu/icache.h"
#include "core/cpu/recompiler/code_pages.h"
#include "core/cpu/recompiler/emitter_impl.h"

namespace psx {

using Xbyak::Label;
using Impl = BlockEmitter::Impl;

// The i-cache check for the words of `run` on its first word's line: the line's tag must be the
// code's physical address (Bus::physical(), as Bus::fetch() tags it) with those words' valid bits
// set (ICache::hit()) and the line not stale. Then the line holds what memory holds, which holds
// the words compiled (ICache::kStale, RecompilerT::compile()).
void Impl::line_check(std::span<const Step> run, Label& fail, Label* fill, Label* filled) {
  const u32 line = run[0].pc & ~15u, tag_bits = Bus::physical(line) & ICache::kTagMask;
  u32 need = 0;
  for (size_t n = 0; n < run.size() && (run[n].pc & ~15u) == line; ++n) need |= 1u << ICache::word(run[n].pc);
  const Xbyak::Address tag = icache_tag(line);
  Label& miss = fill ? *fill : fail;
  cmp(tag, tag_bits | 0xF);  // a tag is the address bits, the valid bits and kStale
  if (need == 0xF) {
    jne(miss, T_NEAR);
  } else {  // mostly the whole line is valid; the words needed alone are tested off the main path
    Label &partial = cold_label(), &hit = cold_label();
    jne(partial, T_NEAR);
    L(hit);
    cold.push_back([this, tag, tag_bits, need, &partial, &hit, &miss] {
      L(partial);
      mov(ecx, tag);
      xor_(ecx, tag_bits | need);
      test(ecx, ICache::kTagMask | ICache::kStale | need);
      jnz(miss, T_NEAR);
      jmp(hit, T_NEAR);
    });
  }
  if (filled) L(*filled);
}

// The i-cache tag of `line` (an address's line), from r12.
Xbyak::Address Impl::icache_tag(u32 line) { return dword[r12 + int(4 * ICache::line(line))]; }

// Whether a miss on pc's line can be filled by native code: cached code in RAM, in KUSEG or
// KSEG0 (the guard has ruled out KSEG1), where the line's tag bits are its address's bits 30-12
// (Bus::physical()), which fill_routine() takes them as.
bool Impl::fills_natively(u32 pc) const {
  return lay.hot_lines && pc < 0xA0000000 && (pc & 0x1FFFFFFF) < 0x00800000;
}

// Where a line check at instruction k (at pc) sends a miss: its fill stub, or nowhere (null: the
// slow path) when the line cannot be filled natively.
Label* Impl::fill_entry(u32 pc, Segment& seg, size_t k) const {
  return fills_natively(pc) ? &seg.fill[k] : nullptr;
}

// The fill of a line that fill_stub() found missing, as ICache::fill() and Bus::icache_miss()
// make it under a four-word block size, shared by every fill stub of the buffer that enters its
// line at word `first`. A game that runs more code in a frame than the i-cache's 4 KiB refills
// hundreds of lines each frame, so the stubs are kept small and give what the fill needs as
// immediates: the line's address in esi (fills_natively()) and the cycles owed at the stub
// (Segment::time_in) in edx. A line that is stale or under a two-word block size is refused:
// nothing changes, and the routine returns 5 bytes past the call, to the stub's jump to its slow
// path. Otherwise the RAM of a line that is not stale still holds every word compiled from it
// (ICache::kStale: CodePages marks the line at a write to any of them, and the blocks written
// are dropped before another block runs), so the fill brings the words this run compiled. It
// starts at the instruction's cycle or at the end of a load's bus access still under way,
// whichever is later: a line whose tag holds the address is refilled whole, any other is
// replaced from word `first` to the line's end, and fetch_hit()'s table then names the line
// where all four words are valid. The time moves on by a word's fetch for each word read, one
// cycle short (the instruction counts its own). Clobbers rcx, rdx, rsi, rdi, r8, r9, r11 and xmm1
// (no native code keeps anything in them across a line check) but keeps eax, which may hold a
// general register (Impl::eax_reg), as the line check itself does.
void Impl::fill_routine(u32 first) {
  const int words_at = int(reinterpret_cast<const char*>(lay.icache_words) -
                           reinterpret_cast<const char*>(lay.icache_tags));
  const Xbyak::Address tag = dword[r12 + r11];  // r11 = 4 * the line's index
  const auto words = [&](u32 w) { return r12 + r11 * 4 + (words_at + int(4 * w)); };
  // A cell of the bus at p, + index: rbx-relative where it can be, through rcx otherwise.
  const auto cell = [&](const void* p, const Xbyak::Reg64& index) {
    if (const auto d = from_context(p)) return rbx + index + *d;
    mov(rcx, reinterpret_cast<u64>(p));
    return rcx + index;
  };
  const auto finish = [&](u32 read, bool line_is_hot) {
    const Xbyak::Address hot = dword[cell(lay.hot_lines, r11)];
    if (line_is_hot) mov(hot, esi);
    else mov(hot, lay.no_hot_line);
    lea(now, ptr[r8 + int(read * lay.fetch_word_cycles) - 1]);
    sub(now, rdx);
    ret();
  };
  Label refuse, other;
  mov(r11d, esi);
  shr(r11d, 2);
  and_(r11d, (ICache::kLines - 1) << 2);  // 4 * ICache::line()
  test(tag, ICache::kStale);
  jnz(refuse, T_NEAR);
  if (const auto d = from_context(lay.cache_control)) {
    test(dword[rbx + *d], lay.icache_block_bits);
  } else {
    mov(rcx, reinterpret_cast<u64>(lay.cache_control));
    test(dword[rcx], lay.icache_block_bits);
  }
  jz(refuse, T_NEAR);
  mov(edi, esi);
  and_(edi, CodePages::kRamSize - 1);
  lea(rdi, ptr[cell(lay.ram, rdi)]);
  movdqu(xmm1, ptr[rdi]);       // the line's RAM
  lea(r8, ptr[now + rdx + 1]);  // the time and the cycle
  mov(rcx, cpu64(lay.load_done_at));
  cmp(r8, rcx);
  cmovb(r8, rcx);
  mov(ecx, esi);
  and_(ecx, ICache::kTagMask & 0x7FFFFFFF);  // the tag bits (fills_natively())
  mov(r9d, tag);
  xor_(r9d, ecx);
  test(r9d, ICache::kTagMask);
  jnz(other, T_NEAR);
  or_(tag, 0xF);
  movdqu(ptr[words(0)], xmm1);
  finish(4, true);
  L(other);  // the new tag keeps kStale, which is clear here
  or_(ecx, (0xFu << first) & 0xF);
  mov(tag, ecx);
  if (first == 0) {
    movdqu(ptr[words(0)], xmm1);
  } else {
    for (u32 w = first; w < 4; ++w) {
      mov(ecx, dword[rdi + int(4 * w)]);
      mov(dword[words(w)], ecx);
    }
  }
  finish(4 - first, first == 0);
  L(refuse);
  add(qword[rsp], kFillRefusal);  // past the stub's jump back, to its jump to the slow path
  ret();
}

// The four fill_routine()s, emitted once for the code buffer where the first block that may need
// one is emitted (again after clear()). What they read of the layout (the cells of the i-cache,
// the bus and the CPU) is the same for every block of a recompiler, which serves one CPU.
void Impl::fill_routines_once() {
  if (!lay.hot_lines || fill_routines[0]) return;
  for (u32 first = 0; first < 4; ++first) {
    align(16);
    fill_routines[first] = getCurr();
    fill_routine(first);
  }
}

// The fetch of rest[0] (instruction k) missing the i-cache, as CpuT::execute_at_pc() and
// Bus::fetch_slow() make it: the instruction's cycle, then the wait for a load's bus access
// still under way, then the fill and a word's time for each word read (fill_routine(), given
// the line and the cycles owed here). Not under a two-word block size (a fill entered at word 0
// would leave words 2 and 3 missing), nor on a stale line, which may be a hit; there
// instruction k takes its slow path, nothing changed. The time is left one cycle short:
// instruction k counts its own cycle.
void Impl::fill_stub(std::span<const Step> rest, size_t k, Segment& seg) {
  L(seg.fill[k]);
  mov(esi, rest[0].pc & ~15u);
  mov(edx, seg.time_in[k]);
  call(fill_routines[ICache::word(rest[0].pc)]);
  const size_t back = getSize();
  jmp(seg.filled[k], T_NEAR);
  if (getSize() - back != kFillRefusal) throw std::logic_error("fill stub: its jump back is not 5 bytes");
  jmp(k == 0 ? seg.slow[0] : seg.slow_native[k], T_NEAR);
}

}  // namespace psx
