// HLE kernel: the C-library calls that call back into the program or end it (psx-spx "BIOS Misc
// Functions", "BIOS Number Functions", "BIOS Function Summary"): qsort A(31h), lsearch A(35h)
// and bsearch A(36h), which call the program's comparison function; atof A(0Bh) and strtod
// A(32h), which fault on the absent COP1 as the BIOS's do; exit A(06h)/B(38h) and _exit A(3Ah).
// The searches run as a state machine resumed each time a comparison returns (Resume::kSearch),
// so interrupts and save states may come between comparisons.
#include "core/bios/hle_bios.h"

#include <cstdio>

#include "core/bus.h"

namespace psx {

namespace {
constexpr u32 kA0 = 0xA0, kB0 = 0xB0;
constexpr u32 kA0r = 4, kA1 = 5, kRa = 31;
}  // namespace

bool HleBios::stdlib_call(u32 table, u32 fn) {
  const u32 a0 = cpu_.reg(kA0r);
  if (table == kB0) {
    if (fn != 0x38) return false;
    program_exit("exit", a0);
    return true;
  }
  if (table != kA0) return false;
  switch (fn) {
    case 0x06: program_exit("exit", a0); return true;
    case 0x3A: program_exit("_exit", a0); return true;
    // atof/strtod: compiled for a COP1 floating point unit the PlayStation lacks (psx-spx): the
    // kernel's stub runs a COP1 instruction, which raises a Coprocessor Unusable exception (CE 1)
    // that no kernel handler resolves, so A(40h) SystemErrorUnresolvedException is called.
    case 0x0B:
    case 0x32: cpu_.set_pc(kFpuStub); return true;
    case 0x31: start_search(Search::kQsort, 0, a0, cpu_.reg(kA1), arg(2), arg(3)); return true;
    case 0x35: start_search(Search::kLsearch, a0, cpu_.reg(kA1), arg(2), arg(3), arg(4)); return true;
    case 0x36: start_search(Search::kBsearch, a0, cpu_.reg(kA1), arg(2), arg(3), arg(4)); return true;
    default: return false;
  }
}

// exit terminates the program and a BIOS then hangs in _exit, which loops forever (psx-spx "A(06h)
// exit", "A(3Ah) _exit"); with nothing left to run, the console stops with the exit code instead.
void HleBios::program_exit(const char* name, u32 code) {
  char msg[96];
  std::snprintf(msg, sizeof msg, "HLE kernel: the program called %s(%d); a BIOS hangs from here", name,
                static_cast<s32>(code));
  if (on_log) on_log(msg);
  if (on_exit) on_exit(code);
  cpu_.stop();
}

// qsort(base, nel, width, cmp), lsearch/bsearch(key, base, nel, width, cmp).
void HleBios::start_search(Search::Op op, u32 key, u32 base, u32 nel, u32 width, u32 cmp) {
  if (search_.op != Search::kNone) {
    if (on_fatal) on_fatal("HLE kernel: qsort/lsearch/bsearch called from a comparison function (not supported)");
    cpu_.stop();
    return;
  }
  search_ = {op, key, base, nel, width, cmp, cpu_.reg(kRa), 0, 0, 0, 0, 0};
  if (op == Search::kQsort) {
    if (nel < 2) return finish_search(0);
    // Each insertion moves elements on the host at once: an array larger than RAM is refused
    // rather than moved for minutes.
    if (static_cast<u64>(nel) * width > Bus::kRamSize) {
      if (on_log) on_log("HLE kernel: qsort of an array larger than RAM (nel * width); array left as is");
      return finish_search(0);
    }
    // The BIOS's qsort moves an element through a width-byte block on the heap, so it works only
    // after InitHeap with that much free (psx-spx "A(31h) qsort").
    search_.temp = heap_alloc(heap_, width);
    if (!search_.temp) {
      if (on_log) on_log("HLE kernel: qsort found no heap block for an element (InitHeap first); array left as is");
      return finish_search(0);
    }
    search_.i = 1, search_.lo = 0, search_.hi = 1;
  } else if (op == Search::kBsearch) {
    search_.lo = 0, search_.hi = nel;
  }
  next_comparison();
}

// Calls the comparison function with two element pointers, or ends the call. lsearch compares
// each element in turn; bsearch halves [lo, hi) around mid; qsort inserts element i into the
// sorted [0, i) at the place found by halving [lo, hi), comparing (element mid, element i).
void HleBios::next_comparison() {
  Search& s = search_;
  auto element = [&](u32 k) { return s.base + k * s.width; };
  switch (s.op) {
    case Search::kLsearch:
      if (s.i >= s.nel) return finish_search(0);
      return compare(s.key, element(s.i));
    case Search::kBsearch:
      if (s.lo >= s.hi) return finish_search(0);
      s.mid = s.lo + (s.hi - s.lo) / 2;
      return compare(s.key, element(s.mid));
    case Search::kQsort:
      while (s.lo >= s.hi) {
        insert_element(s.i, s.lo);
        if (++s.i >= s.nel) {
          heap_free(heap_, s.temp);
          return finish_search(0);
        }
        s.lo = 0, s.hi = s.i;
      }
      s.mid = s.lo + (s.hi - s.lo) / 2;
      return compare(element(s.mid), element(s.i));
    case Search::kNone: return;
  }
}

void HleBios::compare(u32 a, u32 b) {
  cpu_.set_reg(kA1, b);
  call_guest(search_.cmp, a, {Resume::kSearch, 0, 0});
}

// The comparison function returned `result` (negative, zero or positive).
void HleBios::comparison_returned(s32 result) {
  Search& s = search_;
  switch (s.op) {
    case Search::kLsearch:
      if (!result) return finish_search(s.base + s.i * s.width);
      ++s.i;
      break;
    case Search::kBsearch:
      if (!result) return finish_search(s.base + s.mid * s.width);
      if (result < 0) s.hi = s.mid;
      else s.lo = s.mid + 1;
      break;
    case Search::kQsort:  // element mid > element i: i goes before mid; equal ones keep their order
      if (result > 0) s.hi = s.mid;
      else s.lo = s.mid + 1;
      break;
    case Search::kNone: return;
  }
  next_comparison();
}

// Moves element `from` down to `to` (to <= from) through the heap block, the ones between up by one.
void HleBios::insert_element(u32 from, u32 to) {
  const Search& s = search_;
  if (to == from) return;
  const u32 at = s.base + to * s.width;
  for (u32 b = 0; b < s.width; ++b) poke8(s.temp + b, peek8(s.base + from * s.width + b));
  for (u32 b = (from - to) * s.width; b-- > 0;) poke8(at + s.width + b, peek8(at + b));
  for (u32 b = 0; b < s.width; ++b) poke8(at + b, peek8(s.temp + b));
}

void HleBios::finish_search(u32 v0) {
  cpu_.set_reg(kRa, search_.ra);
  search_ = {};
  return_to_caller(v0);
}

}  // namespace psx
