// The i-cache side of compiled blocks (emitter_impl.h): the line checks that let native code
// run only from i-cache hits still holding the compiled words, and the fills native code makes
// itself on a miss in RAM, as Bus::fetch_slow() and ICache::fill() make them.
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
      mov(eax, tag);
      xor_(eax, tag_bits | need);
      test(eax, ICache::kTagMask | ICache::kStale | need);
      jnz(miss, T_NEAR);
      jmp(hit, T_NEAR);
    });
  }
  if (filled) L(*filled);
}

// The i-cache tag of `line` (an address's line) and where its four words begin, from r12.
Xbyak::Address Impl::icache_tag(u32 line) { return dword[r12 + int(4 * ICache::line(line))]; }

Xbyak::RegExp Impl::icache_words(u32 line) const {
  const auto at = reinterpret_cast<const char*>(&lay.icache_words[4 * ICache::line(line)]) -
                  reinterpret_cast<const char*>(lay.icache_tags);
  return r12 + int(at);
}

// Each word of `run` on its first word's line, in the four words at `at` (a line's RAM), must
// be the word compiled. Three or four words are compared at once with the line's compiled words, kept with
// the cold code (SSE2: 37 bytes and 5 instructions on the main path instead of 48-61 bytes and
// 6-8 compares and jumps); clobbers rax and xmm0 (no native code keeps anything there).
void Impl::line_words(std::span<const Step> run, Label& fail, const Xbyak::RegExp& at) {
  const u32 line = run[0].pc & ~15u;
  size_t n = 0;
  while (n < run.size() && (run[n].pc & ~15u) == line) ++n;
  if (n < 3) {
    for (size_t k = 0; k < n; ++k) {
      cmp(dword[at + int(4 * ICache::word(run[k].pc))], run[k].word);
      jne(fail, T_NEAR);
    }
    return;
  }
  std::array<u32, 4> words{};
  u32 lanes = 0;  // pmovmskb's bits: four per word
  for (size_t k = 0; k < n; ++k) {
    const u32 w = ICache::word(run[k].pc);
    words[w] = run[k].word;
    lanes |= 0xFu << (4 * w);
  }
  Label& compiled = cold_label();
  cold.push_back([this, words, &compiled] {
    align(16);  // pcmpeqd's memory operand
    L(compiled);
    for (u32 w : words) dd(w);
  });
  movdqu(xmm0, ptr[at]);
  pcmpeqd(xmm0, ptr[rip + compiled]);
  pmovmskb(eax, xmm0);
  if (lanes != 0xFFFF) and_(eax, lanes);
  cmp(eax, lanes);
  jne(fail, T_NEAR);
}

// Whether a miss on pc's line can be filled by native code: cached code in RAM (the guard has
// ruled out KSEG1).
bool Impl::fills_natively(u32 pc) const { return lay.hot_lines && (pc & 0x1FFFFFFF) < 0x00800000; }

// Where a line check at instruction k (at pc) sends a miss: its fill stub, or nowhere (null: the
// slow path) when the line cannot be filled natively.
Label* Impl::fill_entry(u32 pc, Segment& seg, size_t k) const {
  return fills_natively(pc) ? &seg.fill[k] : nullptr;
}

// ICache::fill() and Bus::icache_miss() for a miss at pc under a four-word block size, from the
// line's RAM at rsi: a line whose tag holds pc's address is refilled whole, any other is
// replaced from pc's word to the line's end; fetch_hit()'s table then names the line where all
// four words are valid. Each way then calls `done` with the number of words read.
template <class Done>
void Impl::icache_fill(u32 pc, Done done) {
  const u32 line = pc & ~15u, first = ICache::word(pc), tag = Bus::physical(line) & ICache::kTagMask;
  const Xbyak::Address tag_at = icache_tag(line);
  const Xbyak::RegExp words = icache_words(line);
  u32* const hot = &lay.hot_lines[ICache::line(line)];
  const auto note_hot = [&](u32 value) {
    if (const auto d = from_context(hot)) {
      mov(dword[rbx + *d], value);
    } else {
      mov(rax, reinterpret_cast<u64>(hot));
      mov(dword[rax], value);
    }
  };
  Label other;
  mov(ecx, tag_at);
  xor_(ecx, tag);
  test(ecx, ICache::kTagMask);
  jnz(other);
  or_(tag_at, 0xF);
  movdqu(xmm0, ptr[rsi]);
  movdqu(ptr[words], xmm0);
  note_hot(line);
  done(4);
  L(other);
  and_(tag_at, ICache::kStale);
  or_(tag_at, tag | ((0xFu << first) & 0xF));
  for (u32 w = first; w < 4; ++w) {
    mov(ecx, dword[rsi + int(4 * w)]);
    mov(dword[words + int(4 * w)], ecx);
  }
  note_hot(first == 0 ? line : lay.no_hot_line);
  done(4 - first);
}

// The fetch of rest[0] (instruction k) missing the i-cache, as CpuT::execute_at_pc() and
// Bus::fetch_slow() make it: the instruction's cycle, then the wait for a load's bus access
// still under way, then the fill and a word's time for each word read. Only a fill of the words
// the run needs from this line that brings exactly the words compiled (RAM still holds them) is
// made here, and not under a two-word block size (a fill entered at word 0 would leave words 2
// and 3 missing), nor on a stale line, which may be a hit; otherwise instruction k takes its
// slow path, nothing changed. The time is left one cycle short: instruction k counts its own
// cycle.
void Impl::fill_stub(std::span<const Step> rest, size_t k, Segment& seg) {
  const u32 line = rest[0].pc & ~15u;
  L(seg.fill[k]);
  Label& slow = k == 0 ? seg.slow[0] : seg.slow_native[k];
  test(icache_tag(line), ICache::kStale);
  jnz(slow, T_NEAR);
  mov(rax, reinterpret_cast<u64>(lay.cache_control));
  test(dword[rax], lay.icache_block_bits);
  jz(slow, T_NEAR);
  mov(rsi, reinterpret_cast<u64>(lay.ram + (line & (CodePages::kRamSize - 1))));
  line_words(rest, slow, rsi);
  lea(r8, ptr[now + int(seg.time_in[k]) + 1]);  // the time (Impl::owed) and the cycle
  mov(rdx, cpu64(lay.load_done_at));
  cmp(r8, rdx);
  cmovb(r8, rdx);
  icache_fill(rest[0].pc, [&](u32 words) {
    lea(now, ptr[r8 + int(words * lay.fetch_word_cycles) - 1 - int(seg.time_in[k])]);
    jmp(seg.filled[k], T_NEAR);
  });
}

}  // namespace psx
