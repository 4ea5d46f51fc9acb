// HLE kernel: vector and stub installation, BIOS call dispatch over the A0h/B0h/C0h tables, TTY
// output calls, system information, and guest memory helpers.
#include "core/bios/hle_bios.h"
#include "core/bios/hle_costs.h"
#include "core/bios/hle_font.h"

#include <algorithm>
#include <cstdio>

#include "core/bus.h"

namespace psx {

namespace {
constexpr u32 kA0 = 0xA0, kB0 = 0xB0, kC0 = 0xC0, kExceptionVector = 0x80;
constexpr u32 kJrRa = 0x03E00008, kSyscall = 0x0000000C;
constexpr u32 kV0 = 2, kA0r = 4, kA1 = 5, kA2 = 6, kA3 = 7, kT1 = 9, kSp = 29, kRa = 31;
constexpr u32 j(u32 target) { return 0x08000000 | ((target >> 2) & 0x03FFFFFF); }
constexpr u32 li_t1(u32 v) { return 0x24090000 | v; }  // ADDIU t1, zero, v
constexpr u32 lw(u32 rt, u32 offset, u32 base) { return 0x8C000000 | base << 21 | rt << 16 | offset; }
constexpr u32 kS0 = 16, kGp = 28, kFp = 30;
}  // namespace

HleBios::HleBios(Cpu& cpu, Bus& bus, Scheduler& sched) : cpu_(cpu), bus_(bus), sched_(sched) {
  krom::map(bus_.bios());
}

void HleBios::install() {
  // Each vector: the marker, then "jr ra; nop" so a disabled hook still returns to the caller.
  for (u32 v : {kA0, kB0, kC0, kExceptionVector}) {
    poke32(v, kMarker);
    poke32(v + 4, kJrRa);
    poke32(v + 8, 0);
  }
  const u32 stubs[] = {kSyscall, 0, j(kA0), 0, j(kB0), 0, j(kB0), li_t1(0x17), kSyscall, 0};
  for (u32 i = 0; i < 10; ++i) poke32(kReturnStub + 4 * i, stubs[i]);
  const u32 delay[] = {0x2508FFFF, 0x1D00FFFE, 0, kJrRa, 0};  // addiu t0,t0,-1; bgtz t0,-2
  for (u32 i = 0; i < 5; ++i) poke32(kDelayStub + 4 * i, delay[i]);
  const u32 boot[] = {0x1D00FFFF, 0x2508FFFF, 0x03400008, 0x00004021};  // bgtz t0,-1; ...; jr k0
  for (u32 i = 0; i < 4; ++i) poke32(kBootStub + 4 * i, boot[i]);
  // Where Exec's program returns, s0 = its headerbuf: the caller's ra, sp, fp, gp and s0 back from
  // it (s0 last, and not in the delay slot: the caller's first instruction may use s0, and a load
  // lands one instruction late), v0 = 1 (hle_exec.cpp).
  const u32 exec_return[7] = {lw(kRa, 0x34, kS0), lw(kSp, 0x28, kS0), lw(kFp, 0x2C, kS0), lw(kGp, 0x30, kS0),
                              lw(kS0, 0x38, kS0), kJrRa, 0x24020001};
  for (u32 i = 0; i < 7; ++i) poke32(kExecReturn + 4 * i, exec_return[i]);
  // ResetEntryInt's exit buffer: ra = ReturnFromException, sp = the exception stack, rest zero.
  for (u32 i = 0; i < 12; ++i) poke32(kDefaultExit + 4 * i, 0);
  poke32(kDefaultExit, kRfeStub);
  poke32(kDefaultExit + 4, kExceptionStack);
  poke32(kFpuStub, 0x44800000);  // mtc1 zero, $f0: COP1 is unusable (SR.CU1 clear), as in atof
  poke32(kFpuStub + 4, 0);
  const char version[] = "psxrl HLE kernel";
  for (u32 i = 0; i < sizeof version; ++i) poke8(kVersionString + i, static_cast<u8>(version[i]));
  poke32(kRamSizeWord, 2);  // RAM size in MiB, as the BIOS writes it at 60h

  kernel_heap_ = {kKernelHeap, kKernelHeapEnd};
  poke32(kKernelHeap, kKernelHeapEnd - kKernelHeap - 4);
  install_tables();
  bus_.flush_icache();  // the code just written must not meet stale cache lines, as at BIOS boot

  // The chains as the BIOS's kernel setup leaves them: the syscall handler in chain 0, DefInt in
  // chain 3, the root counter handlers in chain 1 (C0h:01h, 0Ch, 00h); the pad handler waits
  // for StartPad.
  for (u32 id = 0; id < kNativeCount; ++id) {
    u32 e = kKernelElems + 16 * id;
    poke32(e, 0), poke32(e + 4, 0), poke32(e + 8, kNativeFuncs + 4 * id), poke32(e + 12, 0);
  }
  enqueue(0, kKernelElems + 16 * kSyscallHandler);
  enqueue(3, kKernelElems + 16 * kDefInt);
  for (u32 id : {kRcnt0, kRcnt1, kRcnt2, kRcntVblank}) enqueue(1, kKernelElems + 16 * id);

  // Post-boot state: kernel mode, COP2 enabled, I_MASK 0, inside a critical section (SR.IEc and
  // IM2 clear): OpenBIOS's boot (main/main.c, gameMainThunk, which follows the retail BIOS's boot
  // code) calls EnterCriticalSection before Exec, and the SDKs' start-up leaves it with
  // ExitCriticalSection once their handlers are in place (PSn00bSDK's RestartCallback).
  cpu_.cop0().sr = Cop0::kCU2;
  exit_buf_ = kDefaultExit;
  dispatching_ = return_now_ = unresolved_ = false;
  resume_.clear();
  callbacks_.clear();
  clear_rcnt_ = {1, 1, 1, 1};
  irq_auto_ack_ = 0;
  clear_pad_ = 1;
  pad_buf_ = {};
  pad_started_ = false;
  heap_ = {};
  rand_seed_ = 0x24040001;
  strtok_next_ = 0;
  conf_ = {kMaxEvents, kMaxThreads, 0x801FFF00};
  io_ = {};
  io2_ = {};
  search_ = {};
  io_.files[0].device = io_.files[1].device = kDevTty;  // stdin and stdout, as Exec() leaves them
}

// The program starts where in the video frame a BIOS starts it: after the boot loop's two cycles
// an iteration (I_MASK is 0, so nothing interrupts it).
void HleBios::start_program(u32 entry) {
  constexpr u32 kT0 = 8, kK0 = 26;
  cpu_.set_reg(kK0, entry);
  cpu_.set_reg(kT0, static_cast<u32>(hle_cost::kBootCycles / 2));
  cpu_.set_pc(kBootStub);
}

bool HleBios::handle(u32 pc) {
  u32 p = Bus::physical(pc) & (Bus::kRamSize - 1);
  if (peek32(p) != kMarker) return false;
  land_pending_load();
  if (p != kExceptionVector && via_table(p, pc)) return true;
  switch (p) {
    case kA0: call_a0(cpu_.reg(kT1) & 0xFF); break;
    case kB0: call_b0(cpu_.reg(kT1) & 0xFF); break;
    case kC0: call_c0(cpu_.reg(kT1) & 0xFF); break;
    case kExceptionVector: exception(); break;
    default: return false;
  }
  return true;
}

// A load issued just before the CPU reached a vector (in the delay slot of the jump there, or by
// the instruction an interrupt came after) lands when the kernel's first instruction completes
// (psx-spx "CPU Load/Store Opcodes": the load delay); the kernel's code is not run here, so it lands now, before the
// registers are read, saved in the TCB or the pc is set (which would drop it).
void HleBios::land_pending_load() {
  Cpu::Pending p = cpu_.pending();
  if (!p.load_reg) return;
  cpu_.set_reg(p.load_reg, p.load_value);
  p.load_reg = 0;
  p.load_value = 0;
  cpu_.set_pending(p);
}

void HleBios::return_to_caller(u32 v0) {
  cpu_.set_reg(kV0, v0);
  cpu_.set_pc(cpu_.reg(kRa));
}

// Returns v0 after `cycles` of emulated time spent in the kernel's delay loop (three cycles an
// iteration from the i-cache), so interrupts due meanwhile are taken in it, as they are in a
// BIOS's own code (hle_costs.h).
void HleBios::return_after(u32 v0, Cycles cycles) {
  constexpr u32 kT0 = 8;
  cpu_.set_reg(kV0, v0);
  cpu_.set_reg(kT0, static_cast<u32>(std::max<Cycles>(cycles / 3, 1)));
  cpu_.set_pc(kDelayStub);
}

void HleBios::unsupported(const char* table, u32 fn) {
  char msg[192];
  std::snprintf(msg, sizeof msg,
                "HLE kernel: BIOS call %s:%02Xh (called from 0x%08X) is outside the supported table (see hle_bios.h); "
                "run with --bios",
                table, fn, cpu_.reg(kRa) - 8);
  if (on_fatal) on_fatal(msg);
  cpu_.stop();
}

void HleBios::call_a0(u32 fn) {
  if (string_call(fn) || memory_fill_call(fn) || memory_call(kA0, fn) || io_call(kA0, fn) || tty_call(kA0, fn) ||
      system_call(kA0, fn) || exec_call(fn) || stdlib_call(kA0, fn) || null_call(kA0, fn))
    return;
  unsupported("A0h", fn);
}

void HleBios::call_b0(u32 fn) {
  if (event_call(fn) || interrupt_call(kB0, fn) || thread_call(fn) || table_call(kB0, fn) || memory_call(kB0, fn) || io_call(kB0, fn) || tty_call(kB0, fn) ||
      system_call(kB0, fn) || stdlib_call(kB0, fn))
    return;
  unsupported("B0h", fn);
}

void HleBios::call_c0(u32 fn) {
  if (interrupt_call(kC0, fn) || card_call(kC0, fn) || system_call(kC0, fn) || null_call(kC0, fn)) return;
  unsupported("C0h", fn);
}

// putchar/puts/printf: the console's output, whichever handles are open (the file calls are in
// hle_files.cpp).
bool HleBios::tty_call(u32 table, u32 fn) {
  const u32 a0 = cpu_.reg(kA0r);
  // Each character takes the time a BIOS's TTY output takes (hle_costs.h).
  auto out = [&](const std::string& s, u32 cycles_per_char, u32 v0) {
    print(s);
    return_after(v0, static_cast<Cycles>(cycles_per_char) * s.size());
  };
  auto putchar = [&](u32 c) { out(std::string(1, static_cast<char>(c)), hle_cost::kTtyChar, c); };
  if (table == kA0) {
    switch (fn) {
      case 0x3C: putchar(a0); return true;
      case 0x3E: out(read_string(a0) + "\n", hle_cost::kTtyChar, 1); return true;
      case 0x3F: {
        std::string s = format(a0);
        out(s, hle_cost::kPrintfChar, static_cast<u32>(s.size()));
        return true;
      }
      default: return false;
    }
  }
  switch (fn) {
    case 0x3D: putchar(a0); return true;
    case 0x3F: out(read_string(a0) + "\n", hle_cost::kTtyChar, 1); return true;
    default: return false;
  }
}

// Cache, GPU helpers, configuration and the calls that have nothing to do without a BIOS CD
// driver (psx-spx "BIOS GPU Functions", "BIOS Misc Functions").
bool HleBios::system_call(u32 table, u32 fn) {
  if (table == kB0 && fn == 0x51) {  // Krom2RawAdd: a glyph's address in the ROM's kanji font
    return_to_caller(krom::raw_add(cpu_.reg(kA0r)));
    return true;
  }
  const u32 a0 = cpu_.reg(kA0r), a1 = cpu_.reg(kA1), a2 = cpu_.reg(kA2);
  if (table == kC0) return kernel_setup_call(fn, a0, a1);
  if (table != kA0) return false;
  constexpr u32 kGp0 = 0xBF801810, kGp1 = 0xBF801814;
  switch (fn) {
    case 0x44:  // FlushCache: invalidates the i-cache, so code loaded or patched in RAM runs
      bus_.flush_icache();
      return_after(0, hle_cost::kFlushCache);
      return true;
    case 0x48: io_write(kGp1, a0, 4); return_to_caller(cpu_.reg(kV0)); return true;
    case 0x49: io_write(kGp0, a0, 4); return_to_caller(0); return true;
    case 0x4A:
      for (u32 i = 0; i < a1; ++i) io_write(kGp0, peek32(a0 + 4 * i), 4);
      return_to_caller(0);
      return true;
    case 0x4D: return_to_caller(io_read(kGp1, 4)); return true;
    case 0x4E: {  // gpu_sync (psx-spx "BIOS GPU Functions")
      // With DMA on (GPUSTAT.29-30) it waits for channel 2 to end (D2_CHCR.24), then for
      // GPUSTAT.28 (the command FIFO empty), then turns DMA off by GP1(04h); with DMA off, for
      // bit 28 alone. It spins through A0h until then, so the wait takes the drawing's time and
      // interrupts are taken meanwhile. The BIOS's timeouts (-1 after "a LOT of seconds") are
      // not kept: the wait lasts as long as the GPU or DMA does.
      constexpr u32 kD2Chcr = 0xBF8010A8;
      const u32 stat = io_read(kGp1, 4);
      const bool dma_on = stat & 0x60000000;
      if ((dma_on && (io_read(kD2Chcr, 4) & 0x01000000)) || !(stat & 0x10000000)) {
        cpu_.set_pc(kRetryA0);
        return true;
      }
      if (dma_on) io_write(kGp1, 0x04000000, 4);
      return_to_caller(0);
      return true;
    }
    case 0x99: return_to_caller(0); return true;  // AddDummyTty: the TTY device is always there
    case 0x9F: set_mem(a0); return_to_caller(0); return true;
    case 0x9C: conf_ = {a0, a1, a2}; return_to_caller(0); return true;  // SetConf
    case 0x9D:                                                          // GetConf
      poke32(a0, conf_[0]), poke32(a1, conf_[1]), poke32(a2, conf_[2]);
      return_to_caller(0);
      return true;
    case 0xB4: {  // GetSystemInfo: 0 = kernel date (BCD), 2 = version string, 5 = RAM in KiB
      u32 v = a0 == 0 ? 0x19951204u : a0 == 2 ? kVersionString : a0 == 5 ? 2048u : 0u;
      return_to_caller(v);
      return true;
    }
    default: return false;
  }
}

// InstallExceptionHandlers C(07h) and SysInitMemory C(08h) (psx-spx "BIOS Internal Boot
// Functions"): the kernel's exception vector at 80h again (the kernel's marker instead of the
// BIOS's four opcodes; the BIOS's copy at 0h is not made, a jump to 0 is no kernel call here),
// and the kernel heap's address and size.
bool HleBios::kernel_setup_call(u32 fn, u32 a0, u32 a1) {
  switch (fn) {
    case 0x07:
      poke32(kExceptionVector, kMarker);
      poke32(kExceptionVector + 4, kJrRa);
      poke32(kExceptionVector + 8, 0);
      bus_.flush_icache();
      return_to_caller(0);
      return true;
    case 0x08:
      kernel_heap_ = {a0, a0 + a1};
      poke32(a0, a1 - 4);
      return_to_caller(0);
      return true;
    default: return false;
  }
}

// SetMem(megabytes) A(9Fh): RAM_SIZE (1F801060h) bits 9-11 select 2 MB (4) or 8 MB (5) of
// mapped RAM (psx-spx "Memory Control"), and the size goes to [60h]; other sizes change nothing.
void HleBios::set_mem(u32 megabytes) {
  constexpr u32 kRamSizeReg = 0xBF801060, kWindow = 7u << 9;
  if (megabytes != 2 && megabytes != 8) return;
  const u32 v = io_read(kRamSizeReg, 4);
  io_write(kRamSizeReg, (v & ~kWindow) | (megabytes == 2 ? 4u : 5u) << 9, 4);
  poke32(kRamSizeWord, megabytes);
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
  if (p >= 0x00800000) return;
  bus_.ram()[p & (Bus::kRamSize - 1)] = v;
  bus_.host_wrote_ram(p & (Bus::kRamSize - 1), 1);
}

void HleBios::poke32(u32 addr, u32 v) {
  for (u32 i = 0; i < 4; ++i) poke8(addr + i, static_cast<u8>(v >> (8 * i)));
}

u32 HleBios::io_read(u32 addr, u32 width) {
  u32 v = 0;
  if (width == 4) bus_.read32(addr, v);
  else bus_.read16(addr, v);
  return v;
}

void HleBios::io_write(u32 addr, u32 v, u32 width) {
  if (width == 4) bus_.write32(addr, v);
  else bus_.write16(addr, v);
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
  const u32 version = s.section("HLEK", 6, 2);
  if (version == 2) {
    load_v2_state(s);
  } else {
    s.pod(exit_buf_);
    s.boolean(dispatching_), s.boolean(return_now_), s.boolean(unresolved_);
    s.pod(chain_prio_), s.pod(chain_elem_);
    s.vec(resume_, 256);
    s.vec(callbacks_, 256);
    s.pod(clear_rcnt_), s.pod(irq_auto_ack_), s.pod(clear_pad_), s.pod(pad_buf_);
    s.boolean(pad_started_);
    s.pod(heap_), s.pod(kernel_heap_);
    s.pod(rand_seed_), s.pod(strtok_next_), s.pod(conf_);
  }
  // Version 4 added the file functions' state; older states had no file open but stdin/stdout.
  HleIoState boot_io;
  boot_io.files[0].device = boot_io.files[1].device = kDevTty;
  s.pod_since(version, 4, io_, boot_io);
  s.pod_since(version, 5, io2_, HleIoState2{});  // version 5: card find mode, _card_chan, CdAsync*
  s.pod_since(version, 6, search_, Search{});     // version 6: a qsort/lsearch/bsearch under way
  s.end_section("HLEK");
}

// Version 2 kept the register save area, the chain heads and the events on the host. An HLE
// run's state (its chains are never all empty) gets the kernel tables written into its RAM,
// which was loaded before this section, and those three copied into them.
void HleBios::load_v2_state(StateIO& s) {
  struct OldEvent {
    u32 cls, spec, mode, func, status;
  };
  std::array<u32, 32> regs{};
  u32 hi = 0, lo = 0, sr = 0, epc = 0;
  std::array<u32, 4> chains{};
  std::array<OldEvent, kMaxEvents> events{};
  s.pod(regs), s.pod(hi), s.pod(lo), s.pod(sr), s.pod(epc);
  s.pod(exit_buf_), s.pod(chains);
  s.boolean(dispatching_), s.boolean(return_now_);
  s.pod(chain_prio_), s.pod(chain_elem_);
  s.vec(resume_, 256);
  s.vec(callbacks_, 256);
  s.pod(events);
  s.pod(clear_rcnt_), s.pod(clear_pad_), s.pod(pad_buf_);
  s.boolean(pad_started_);
  s.pod(heap_), s.pod(kernel_heap_);
  s.pod(rand_seed_), s.pod(strtok_next_), s.pod(conf_);
  unresolved_ = false;
  irq_auto_ack_ = 0;
  if (chains == std::array<u32, 4>{}) return;
  install_tables();
  u32 tcb = current_tcb();
  for (u32 r = 0; r < 32; ++r) poke32(tcb + 8 + 4 * r, regs[r]);
  const u32 tail[5] = {epc, hi, lo, sr, 0};
  for (u32 i = 0; i < 5; ++i) poke32(tcb + 0x88 + 4 * i, tail[i]);
  for (u32 p = 0; p < 4; ++p) set_chain_head(p, chains[p]);
  u32 evcb = peek32(kTables + 0x20);
  for (u32 i = 0; i < kMaxEvents; ++i) {
    const OldEvent& e = events[i];
    const u32 fields[5] = {e.cls, e.status, e.spec, e.mode, e.func};
    for (u32 k = 0; k < 5; ++k) poke32(evcb + i * kEvcbSize + 4 * k, fields[k]);
  }
}

}  // namespace psx
