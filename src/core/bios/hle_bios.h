// HLE kernel: runs PlayStation programs without a Sony BIOS. It puts the hardware in its post-boot
// state, owns the exception vector, and services the BIOS calls simple programs make through the
// A0h/B0h/C0h vectors. Supported calls (everything else stops the console with a clear message):
//   A0h:1Bh strlen  A0h:2Ah memcpy  A0h:2Bh memset  A0h:3Ch putchar  A0h:3Eh puts  A0h:3Fh printf
//   A0h:44h FlushCache
//   B0h:17h ReturnFromException  B0h:18h SetDefaultExitFromException
//   B0h:19h SetCustomExitFromException  B0h:3Dh putchar  B0h:3Fh puts
//   SYSCALL a0=0 NoFunction, a0=1 EnterCriticalSection, a0=2 ExitCriticalSection
// With a real BIOS the console keeps only the putchar hooks (to print) and the shell-entry hook.
#pragma once
#include <array>
#include <functional>
#include <set>
#include <string>

#include "core/cpu/cpu.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class Bus;

class HleBios {
 public:
  HleBios(Cpu& cpu, Bus& bus) : cpu_(cpu), bus_(bus) {}

  // Writes the kernel's vectors into RAM and sets SR/I_MASK as the BIOS leaves them at boot.
  void install();
  // Handles the CPU reaching a hooked vector. Returns false when the vector holds program code
  // (the program replaced the kernel's handler), so the CPU should just run it.
  bool handle(u32 pc);

  std::function<void(char)> on_tty;
  std::function<void(const std::string&)> on_log;
  std::function<void(const std::string&)> on_fatal;

  void do_state(StateIO& s);

  // Marker instruction the kernel places at each vector it owns: LUI $zero, 0x484C ("HL").
  static constexpr u32 kMarker = 0x3C00484C;

 private:
  void call_a0(u32 fn);
  void call_b0(u32 fn);
  void exception();
  void return_to_caller(u32 v0);
  void unsupported(const char* table, u32 fn);

  u8 peek8(u32 addr) const;
  u32 peek32(u32 addr) const;
  void poke8(u32 addr, u8 v);
  std::string read_string(u32 addr) const;
  u32 arg(u32 i) const;
  std::string format(u32 fmt_addr) const;
  void print(const std::string& s);

  Cpu& cpu_;
  Bus& bus_;
  // Registers saved when an interrupt is handed to the program's custom exit
  // (SetCustomExitFromException); ReturnFromException restores them.
  std::array<u32, 32> saved_regs_{};
  u32 saved_hi_ = 0, saved_lo_ = 0;
  u32 custom_exit_ = 0;
  std::set<u32> warned_;
};

}  // namespace psx
