// HLE kernel: vector installation, BIOS call dispatch, printf and exception handling.
#include "core/bios/hle_bios.h"

#include <cstdio>

#include "core/bus.h"

namespace psx {

namespace {
constexpr u32 kA0 = 0xA0, kB0 = 0xB0, kC0 = 0xC0, kExceptionVector = 0x80;
constexpr u32 kJrRa = 0x03E00008;
enum Reg : u32 { kV0 = 2, kA0r = 4, kA1 = 5, kA2 = 6, kA3 = 7, kT1 = 9, kSp = 29, kFp = 30, kRa = 31 };
}  // namespace

void HleBios::install() {
  // Each vector: the marker, then "jr ra; nop" so a disabled hook still returns to the caller.
  for (u32 v : {kA0, kB0, kC0, kExceptionVector}) {
    Bus::store_le32(bus_.ram() + v, kMarker);
    Bus::store_le32(bus_.ram() + v + 4, kJrRa);
    Bus::store_le32(bus_.ram() + v + 8, 0);
  }
  // Post-boot state: kernel mode, COP2 enabled, hardware interrupts unmasked in SR, I_MASK 0.
  cpu_.cop0().sr = Cop0::kCU2 | Cop0::kIP2 | Cop0::kIEc;
  custom_exit_ = 0;
}

bool HleBios::handle(u32 pc) {
  u32 p = Bus::physical(pc) & (Bus::kRamSize - 1);
  if (peek32(p) != kMarker) return false;
  switch (p) {
    case kA0: call_a0(cpu_.reg(kT1) & 0xFF); break;
    case kB0: call_b0(cpu_.reg(kT1) & 0xFF); break;
    case kC0: unsupported("C0h", cpu_.reg(kT1) & 0xFF); break;
    case kExceptionVector: exception(); break;
    default: return false;
  }
  return true;
}

void HleBios::return_to_caller(u32 v0) {
  cpu_.set_reg(kV0, v0);
  cpu_.set_pc(cpu_.reg(kRa));
}

void HleBios::unsupported(const char* table, u32 fn) {
  char msg[160];
  std::snprintf(msg, sizeof msg,
                "HLE kernel: BIOS call %s:%02Xh is outside the supported table (see hle_bios.h); run with --bios",
                table, fn);
  if (on_fatal) on_fatal(msg);
  cpu_.stop();
}

void HleBios::call_a0(u32 fn) {
  switch (fn) {
    case 0x1B: return_to_caller(static_cast<u32>(read_string(cpu_.reg(kA0r)).size())); break;  // strlen
    case 0x2A: {  // memcpy(dst, src, len)
      u32 d = cpu_.reg(kA0r), s = cpu_.reg(kA1), n = cpu_.reg(kA2);
      for (u32 i = 0; i < n; ++i) poke8(d + i, peek8(s + i));
      return_to_caller(d);
      break;
    }
    case 0x2B: {  // memset(dst, value, len)
      u32 d = cpu_.reg(kA0r), n = cpu_.reg(kA2);
      for (u32 i = 0; i < n; ++i) poke8(d + i, static_cast<u8>(cpu_.reg(kA1)));
      return_to_caller(d);
      break;
    }
    case 0x3C: print(std::string(1, static_cast<char>(cpu_.reg(kA0r)))); return_to_caller(cpu_.reg(kA0r)); break;
    case 0x3E: print(read_string(cpu_.reg(kA0r)) + "\n"); return_to_caller(1); break;  // puts
    case 0x3F: {                                                                       // printf
      std::string s = format(cpu_.reg(kA0r));
      print(s);
      return_to_caller(static_cast<u32>(s.size()));
      break;
    }
    case 0x44: return_to_caller(0); break;  // FlushCache: the emulated caches are always coherent
    default: unsupported("A0h", fn); break;
  }
}

void HleBios::call_b0(u32 fn) {
  switch (fn) {
    case 0x17:  // ReturnFromException: resume the interrupted program with its registers
      for (u32 r = 1; r < 32; ++r) cpu_.set_reg(r, saved_regs_[r]);
      cpu_.set_hi(saved_hi_);
      cpu_.set_lo(saved_lo_);
      cpu_.cop0().sr = (cpu_.cop0().sr & ~0xFu) | ((cpu_.cop0().sr >> 2) & 0xF);
      cpu_.set_pc(cpu_.cop0().epc);
      break;
    case 0x18: custom_exit_ = 0; return_to_caller(0); break;                 // SetDefaultExitFromException
    case 0x19: custom_exit_ = cpu_.reg(kA0r); return_to_caller(0); break;   // SetCustomExitFromException
    case 0x3D: print(std::string(1, static_cast<char>(cpu_.reg(kA0r)))); return_to_caller(cpu_.reg(kA0r)); break;
    case 0x3F: print(read_string(cpu_.reg(kA0r)) + "\n"); return_to_caller(1); break;
    default: unsupported("B0h", fn); break;
  }
}

void HleBios::exception() {
  Cop0& c = cpu_.cop0();
  u32 code = (c.cause >> 2) & 0x1F;
  auto rfe = [&] { c.sr = (c.sr & ~0xFu) | ((c.sr >> 2) & 0xF); };
  if (code == static_cast<u32>(Exception::Syscall)) {
    // The saved IEp (SR bit 2) is what RFE restores, so the critical section calls edit it.
    u32 fn = cpu_.reg(kA0r);
    if (fn == 1) {
      cpu_.set_reg(kV0, (c.sr & 0x404) == 0x404 ? 1 : 0);
      c.sr &= ~0x404u;
    } else if (fn == 2) {
      c.sr |= 0x404;
    }
    rfe();
    cpu_.set_pc(c.epc + 4);
    return;
  }
  if (code == static_cast<u32>(Exception::Interrupt)) {
    if (custom_exit_) {
      // Like the BIOS: save the program's registers, then longjmp into its handler through the
      // buffer it registered (ra, sp, fp, s0-s7, gp) with v0 = 1.
      for (u32 r = 0; r < 32; ++r) saved_regs_[r] = cpu_.reg(r);
      saved_hi_ = cpu_.hi();
      saved_lo_ = cpu_.lo();
      u32 b = custom_exit_;
      u32 ra = peek32(b);
      cpu_.set_reg(kSp, peek32(b + 4));
      cpu_.set_reg(kFp, peek32(b + 8));
      for (u32 i = 0; i < 8; ++i) cpu_.set_reg(16 + i, peek32(b + 12 + 4 * i));
      cpu_.set_reg(28, peek32(b + 44));
      cpu_.set_reg(kV0, 1);
      cpu_.set_pc(ra);
      return;
    }
    if (warned_.insert(0x100).second && on_log)
      on_log("HLE kernel: interrupt with no handler registered; returning to the program");
    rfe();
    cpu_.set_pc(c.epc);
    return;
  }
  char msg[128];
  std::snprintf(msg, sizeof msg, "unhandled CPU exception %u (Cause 0x%08X) at EPC 0x%08X, BadVaddr 0x%08X", code,
                c.cause, c.epc, c.badvaddr);
  if (on_fatal) on_fatal(msg);
  cpu_.stop();
}

u8 HleBios::peek8(u32 addr) const {
  u32 p = Bus::physical(addr);
  return p < 0x00800000 ? bus_.ram()[p & (Bus::kRamSize - 1)] : 0;
}

u32 HleBios::peek32(u32 addr) const {
  return peek8(addr) | peek8(addr + 1) << 8 | peek8(addr + 2) << 16 | static_cast<u32>(peek8(addr + 3)) << 24;
}

void HleBios::poke8(u32 addr, u8 v) {
  u32 p = Bus::physical(addr);
  if (p < 0x00800000) bus_.ram()[p & (Bus::kRamSize - 1)] = v;
}

std::string HleBios::read_string(u32 addr) const {
  std::string s;
  for (u32 i = 0; i < 4096; ++i) {
    char c = static_cast<char>(peek8(addr + i));
    if (!c) break;
    s += c;
  }
  return s;
}

// Argument i of a call (O32 ABI: a0-a3, then the stack slots at sp + 4*i).
u32 HleBios::arg(u32 i) const { return i < 4 ? cpu_.reg(kA0r + i) : peek32(cpu_.reg(kSp) + 4 * i); }

void HleBios::print(const std::string& s) {
  if (on_tty)
    for (char c : s) on_tty(c);
}

void HleBios::do_state(StateIO& s) {
  s.section("HLEK", 1);
  s.pod(saved_regs_);
  s.pod(saved_hi_), s.pod(saved_lo_), s.pod(custom_exit_);
}

}  // namespace psx
