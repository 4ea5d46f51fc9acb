// HLE kernel: the C library functions of table A0h (psx-spx "BIOS String Functions", "BIOS
// Memory Fill/Copy/Compare", "BIOS Number/String/Character Conversion"): string, memory, ctype
// and number conversion, setjmp/longjmp and rand. They follow the C standard; where psx-spx
// documents a BIOS quirk for NULL pointers (string functions return 0 instead of crashing), the
// quirk is kept.
#include "core/bios/hle_bios.h"

namespace psx {

namespace {
constexpr u32 kA0r = 4, kA1 = 5, kA2 = 6, kRa = 31;
bool is_space(u8 c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
u8 to_upper(u8 c) { return c >= 'a' && c <= 'z' ? c - 32 : c; }
u8 to_lower(u8 c) { return c >= 'A' && c <= 'Z' ? c + 32 : c; }
}  // namespace

// memcmp/strcmp/strncmp: the difference of the first differing bytes (as unsigned chars).
s32 HleBios::compare(u32 a, u32 b, u32 n, bool stop_at_nul) const {
  for (u32 i = 0; i < n; ++i) {
    u8 x = peek8(a + i), y = peek8(b + i);
    if (x != y) return static_cast<s32>(x) - static_cast<s32>(y);
    if (stop_at_nul && !x) return 0;
  }
  return 0;
}

// strtol(src, end, base): optional white space and sign, "0x" for base 16 or 0, a leading 0
// selects octal for base 0; *end gets the first unused character (or src when no digits).
u32 HleBios::str_to_long(u32 src, u32 end_ptr, u32 base) {
  u32 p = src;
  while (is_space(peek8(p))) ++p;
  bool neg = peek8(p) == '-';
  if (neg || peek8(p) == '+') ++p;
  if ((base == 0 || base == 16) && peek8(p) == '0' && to_lower(peek8(p + 1)) == 'x') {
    p += 2;
    base = 16;
  } else if (base == 0) {
    base = peek8(p) == '0' ? 8 : 10;
  }
  u32 v = 0, digits = 0;
  for (;; ++p, ++digits) {
    u8 c = to_lower(peek8(p));
    u32 d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'z' ? c - 'a' + 10 : 99;
    if (d >= base) break;
    v = v * base + d;
  }
  if (end_ptr) poke32(end_ptr, digits ? p : src);
  return neg ? 0u - v : v;
}

bool HleBios::string_call(u32 fn) {
  const u32 a0 = cpu_.reg(kA0r), a1 = cpu_.reg(kA1), a2 = cpu_.reg(kA2);
  auto len = [&](u32 s) {
    u32 n = 0;
    while (peek8(s + n) && n < 0x200000) ++n;
    return n;
  };
  auto find = [&](u32 s, u8 c, bool last) {
    u32 hit = 0;
    for (u32 p = s;; ++p) {
      if (peek8(p) == c) {
        hit = p;
        if (!last) break;
      }
      if (!peek8(p)) break;
    }
    return hit;
  };
  auto in_set = [&](u32 set, u8 c) {
    for (u32 p = set; peek8(p); ++p)
      if (peek8(p) == c) return true;
    return false;
  };
  switch (fn) {
    case 0x0C:
    case 0x0D: return_to_caller(str_to_long(a0, a1, a2)); return true;  // strtol, strtoul
    case 0x0E:
    case 0x0F: return_to_caller(static_cast<s32>(a0) < 0 ? 0u - a0 : a0); return true;  // abs, labs
    case 0x10:
    case 0x11: return_to_caller(str_to_long(a0, 0, 10)); return true;  // atoi, atol
    case 0x13:                                                         // setjmp(buf)
      poke32(a0, cpu_.reg(kRa)), poke32(a0 + 4, cpu_.reg(29)), poke32(a0 + 8, cpu_.reg(30));
      for (u32 i = 0; i < 8; ++i) poke32(a0 + 12 + 4 * i, cpu_.reg(16 + i));
      poke32(a0 + 44, cpu_.reg(28));
      return_to_caller(0);
      return true;
    case 0x14:  // longjmp(buf, value)
      cpu_.set_reg(29, peek32(a0 + 4)), cpu_.set_reg(30, peek32(a0 + 8));
      for (u32 i = 0; i < 8; ++i) cpu_.set_reg(16 + i, peek32(a0 + 12 + 4 * i));
      cpu_.set_reg(28, peek32(a0 + 44));
      cpu_.set_reg(kRa, peek32(a0));
      return_to_caller(a1);
      return true;
    case 0x15:  // strcat(dst, src)
    case 0x16: {  // strncat(dst, src, n)
      if (!a0 || !a1) return return_to_caller(0), true;
      u32 d = a0 + len(a0), n = fn == 0x15 ? 0xFFFFFFFF : a2, i = 0;
      for (; i < n && peek8(a1 + i); ++i) poke8(d + i, peek8(a1 + i));
      poke8(d + i, 0);
      return_to_caller(a0);
      return true;
    }
    case 0x17:
    case 0x18: {  // strcmp, strncmp
      if (!a0 || !a1) return return_to_caller(a0 == a1 ? 0 : a0 ? 1 : 0xFFFFFFFF), true;
      return_to_caller(static_cast<u32>(compare(a0, a1, fn == 0x17 ? 0xFFFFFFFF : a2, true)));
      return true;
    }
    case 0x19: {  // strcpy
      if (!a0 || !a1) return return_to_caller(0), true;
      u32 i = 0;
      for (; peek8(a1 + i); ++i) poke8(a0 + i, peek8(a1 + i));
      poke8(a0 + i, 0);
      return_to_caller(a0);
      return true;
    }
    case 0x1A: {  // strncpy: pads the rest of the n bytes with zeros
      if (!a0 || !a1) return return_to_caller(0), true;
      bool ended = false;
      for (u32 i = 0; i < a2; ++i) {
        u8 c = ended ? 0 : peek8(a1 + i);
        ended = ended || !c;
        poke8(a0 + i, c);
      }
      return_to_caller(a0);
      return true;
    }
    case 0x1B: return_to_caller(a0 ? len(a0) : 0); return true;
    case 0x1C:
    case 0x1E: return_to_caller(a0 ? find(a0, static_cast<u8>(a1), false) : 0); return true;  // index, strchr
    case 0x1D:
    case 0x1F: return_to_caller(a0 ? find(a0, static_cast<u8>(a1), true) : 0); return true;  // rindex, strrchr
    case 0x20: {  // strpbrk
      u32 p = a0;
      while (p && peek8(p) && !in_set(a1, peek8(p))) ++p;
      return_to_caller(p && peek8(p) ? p : 0);
      return true;
    }
    case 0x21:
    case 0x22: {  // strspn, strcspn
      u32 n = 0;
      while (a0 && peek8(a0 + n) && in_set(a1, peek8(a0 + n)) == (fn == 0x21)) ++n;
      return_to_caller(n);
      return true;
    }
    case 0x23: {  // strtok(str, delimiters): continues after the last token when str is 0
      u32 p = a0 ? a0 : strtok_next_;
      while (p && peek8(p) && in_set(a1, peek8(p))) ++p;
      if (!p || !peek8(p)) {
        strtok_next_ = 0;
        return_to_caller(0);
        return true;
      }
      u32 e = p;
      while (peek8(e) && !in_set(a1, peek8(e))) ++e;
      strtok_next_ = peek8(e) ? e + 1 : 0;
      if (peek8(e)) poke8(e, 0);
      return_to_caller(p);
      return true;
    }
    case 0x24: {  // strstr
      if (!a0 || !a1) return return_to_caller(0), true;
      u32 n = len(a1), hit = 0;
      for (u32 p = a0; !hit; ++p) {
        if (compare(p, a1, n, false) == 0) hit = p;
        if (!peek8(p)) break;
      }
      return_to_caller(hit);
      return true;
    }
    case 0x25: return_to_caller(to_upper(static_cast<u8>(a0))); return true;
    case 0x26: return_to_caller(to_lower(static_cast<u8>(a0))); return true;
    case 0x2F:  // rand: x = x * 41C64E6Dh + 3039h, result bits 16-30
      rand_seed_ = rand_seed_ * 0x41C64E6D + 0x3039;
      return_to_caller((rand_seed_ >> 16) & 0x7FFF);
      return true;
    case 0x30: rand_seed_ = a0; return_to_caller(0); return true;  // srand
    default: return false;
  }
}

bool HleBios::memory_fill_call(u32 fn) {
  const u32 a0 = cpu_.reg(kA0r), a1 = cpu_.reg(kA1), a2 = cpu_.reg(kA2);
  auto move = [&](u32 dst, u32 src, u32 n) {
    if (dst <= src || dst >= src + n)
      for (u32 i = 0; i < n; ++i) poke8(dst + i, peek8(src + i));
    else
      for (u32 i = n; i-- > 0;) poke8(dst + i, peek8(src + i));
  };
  switch (fn) {
    case 0x27: move(a1, a0, a2); return_to_caller(a1); return true;  // bcopy(src, dst, n)
    case 0x28:                                                         // bzero(dst, n)
      for (u32 i = 0; i < a1; ++i) poke8(a0 + i, 0);
      return_to_caller(a0);
      return true;
    case 0x29:
    case 0x2D: return_to_caller(static_cast<u32>(compare(a0, a1, a2, false))); return true;  // bcmp, memcmp
    case 0x2A:  // memcpy (a forward byte copy, as the BIOS does)
      for (u32 i = 0; i < a2; ++i) poke8(a0 + i, peek8(a1 + i));
      return_to_caller(a0);
      return true;
    case 0x2B:
      for (u32 i = 0; i < a2; ++i) poke8(a0 + i, static_cast<u8>(a1));
      return_to_caller(a0);
      return true;
    case 0x2C: move(a0, a1, a2); return_to_caller(a0); return true;  // memmove
    case 0x2E: {                                                       // memchr
      u32 hit = 0;
      for (u32 i = 0; i < a2 && !hit; ++i)
        if (peek8(a0 + i) == static_cast<u8>(a1)) hit = a0 + i;
      return_to_caller(hit);
      return true;
    }
    default: return false;
  }
}

}  // namespace psx
