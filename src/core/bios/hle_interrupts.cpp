// HLE kernel: the exception handler as the BIOS runs it (psx-spx "BIOS Interrupt/Exception
// Handling"): register save area, the four priority chains of interrupt handlers, the exit
// buffer (HookEntryInt/ResetEntryInt), ReturnFromException, critical sections, the kernel's own
// root counter / pad / DefInt handlers, the BIOS timer functions and calls into program code.
#include <cstdio>

#include "core/bios/hle_bios.h"
#include "core/bios/hle_costs.h"
#include "core/bus.h"
#include "core/sio/sio_device.h"

namespace psx {

namespace {
constexpr u32 kV0 = 2, kA0r = 4, kA1 = 5, kSp = 29, kFp = 30, kRa = 31, kGp = 28;
// TCB offsets (psx-spx "BIOS Thread Functions"): r0-r31 from 08h, then EPC, HI, LO, SR, Cause.
constexpr u32 kTcbRegs = 0x08, kTcbEpc = 0x88, kTcbHi = 0x8C, kTcbLo = 0x90, kTcbSr = 0x94, kTcbCause = 0x98;
constexpr u32 kIStat = 0xBF801070, kIMask = 0xBF801074;
constexpr u32 kB0 = 0xB0, kC0 = 0xC0;
// RFE: pop the KU/IE stack (previous -> current, old -> previous).
inline u32 rfe(u32 sr) { return (sr & ~0xFu) | ((sr >> 2) & 0xF); }
// Books an interrupt's kernel time step by step, as the BIOS's handler takes it (hle_costs.h):
// saved_cause is the Cause the TCB holds for the exception being handled; the other exceptions
// take none here.
void book(Scheduler& sched, u32 saved_cause, u32 cycles) {
  if (((saved_cause >> 2) & 0x1F) == static_cast<u32>(Exception::Interrupt)) sched.advance(cycles);
}
}  // namespace

void HleBios::exception() {
  Cop0& c = cpu_.cop0();
  u32 code = (c.cause >> 2) & 0x1F;
  if (code == static_cast<u32>(Exception::Syscall) && (c.epc == kReturnStub || c.epc == kExitStub)) {
    kernel_stub_syscall();
    return;
  }
  save_thread_registers();
  if (code == static_cast<u32>(Exception::Syscall)) {
    syscall();
    return;
  }
  dispatching_ = true;
  return_now_ = false;
  unresolved_ = code != static_cast<u32>(Exception::Interrupt);
  book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kExceptionEntry + hle_cost::kChainPriority);
  chain_prio_ = 0;
  chain_elem_ = chain_head(0);
  // The hardware executes a GTE command at the interrupted address before taking the
  // interrupt, so the BIOS resumes after it (psx-spx "COP0 - Interrupt Handling").
  u32 tcb = current_tcb(), epc = peek32(tcb + kTcbEpc);
  if (!unresolved_ && !(c.cause & Cop0::kBD) && (peek32(epc) >> 25) == 0x25) poke32(tcb + kTcbEpc, epc + 4);
  dispatch_next();
}

// Cause and EPC as the exception saved them in the TCB (an event callback run since has taken
// the kernel's return SYSCALL, which changed the COP0 registers).
void HleBios::fail_exception() {
  u32 tcb = current_tcb(), cause = peek32(tcb + kTcbCause);
  char msg[192];
  const u32 epc = peek32(tcb + kTcbEpc);
  std::snprintf(msg, sizeof msg, "unhandled CPU exception %u (Cause 0x%08X) at EPC 0x%08X, BadVaddr 0x%08X%s",
                (cause >> 2) & 0x1F, cause, epc, cpu_.cop0().badvaddr,
                epc == kFpuStub ? " (atof/strtod: the BIOS's code uses the absent COP1, psx-spx)" : "");
  dispatching_ = false;
  if (on_fatal) on_fatal(msg);
  cpu_.stop();
}

// SYSCALL: the registers are in the TCB; the function edits them there, as the BIOS's syscall
// handler does, and ReturnFromException resumes after the SYSCALL instruction.
// The SYSCALLs of the kernel's own stubs: a program function it called returned, or the
// program returned from its entry point.
void HleBios::kernel_stub_syscall() {
  Cop0& c = cpu_.cop0();
  if (c.epc == kReturnStub) {
    c.sr = rfe(c.sr);
    guest_returned();
    return;
  }
  if (on_fatal) on_fatal("the program returned from its entry point to the kernel (HLE kernel: nothing to return to)");
  cpu_.stop();
}

void HleBios::syscall() {
  Cop0& c = cpu_.cop0();
  sched_.advance(hle_cost::kSyscall);
  u32 tcb = current_tcb();
  auto reg = [&](u32 r) { return tcb + kTcbRegs + 4 * r; };
  poke32(tcb + kTcbEpc, c.epc + 4);
  // The saved IEp and IM2 (SR bits 2 and 10) are what RFE restores, so the critical section
  // calls edit them (psx-spx "SYS(01h) EnterCriticalSection").
  u32 sr = peek32(tcb + kTcbSr);
  switch (peek32(reg(kA0r))) {
    case 0: break;
    case 1:
      poke32(reg(kV0), (sr & 0x404) == 0x404 ? 1 : 0);
      poke32(tcb + kTcbSr, sr & ~0x404u);
      break;
    case 2: poke32(tcb + kTcbSr, sr | 0x404); break;
    case 3:  // ChangeThreadSubFunction(tcb): the return goes to that thread
      poke32(reg(kV0), 1);
      poke32(peek32(kTables + 8), peek32(reg(kA1)));
      break;
    default: deliver_event(0xF0000010, 0x4000); break;
  }
  return_from_exception();
}

void HleBios::save_thread_registers() {
  u32 tcb = current_tcb();
  for (u32 r = 0; r < 32; ++r) poke32(tcb + kTcbRegs + 4 * r, cpu_.reg(r));
  poke32(tcb + kTcbEpc, cpu_.cop0().epc);
  poke32(tcb + kTcbHi, cpu_.hi());
  poke32(tcb + kTcbLo, cpu_.lo());
  poke32(tcb + kTcbSr, cpu_.cop0().sr);
  poke32(tcb + kTcbCause, cpu_.cop0().cause);
}

// B0h:17h: restores R1-R31 (except k0), HI, LO and SR from the current thread's TCB, then
// RFE + jump to its EPC.
void HleBios::return_from_exception() {
  u32 tcb = current_tcb();
  if (((peek32(tcb + kTcbCause) >> 2) & 0x1F) == static_cast<u32>(Exception::Interrupt))
    sched_.advance(hle_cost::kInterruptReturn);
  for (u32 r = 1; r < 32; ++r)
    if (r != 26) cpu_.set_reg(r, peek32(tcb + kTcbRegs + 4 * r));
  cpu_.set_hi(peek32(tcb + kTcbHi));
  cpu_.set_lo(peek32(tcb + kTcbLo));
  cpu_.cop0().sr = rfe(peek32(tcb + kTcbSr));
  // Kernel calls still pending for this exception are abandoned with it.
  while (!resume_.empty() && resume_.back().in_dispatch) resume_.pop_back();
  if (dispatching_) callbacks_.clear();
  dispatching_ = unresolved_ = false;
  cpu_.set_pc(peek32(tcb + kTcbEpc));
  cpu_.note_exception_return();
}

// Walks the chains from where it stopped; returns whenever a program function has been called.
void HleBios::dispatch_next() {
  for (;;) {
    if (!callbacks_.empty()) {
      u32 f = callbacks_.front();
      callbacks_.erase(callbacks_.begin());
      call_guest(f, 0, {Resume::kDispatch, 0, 1});
      return;
    }
    if (return_now_) {
      return_from_exception();
      return;
    }
    if (!chain_elem_) {
      if (++chain_prio_ >= 4) break;
      book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kChainPriority);
      chain_elem_ = chain_head(chain_prio_);
      continue;
    }
    book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kChainElement);
    u32 elem = chain_elem_;
    chain_elem_ = peek32(elem);
    u32 func2 = peek32(elem + 4), func1 = peek32(elem + 8);
    if (func1 >= kNativeFuncs && func1 < kNativeFuncs + 4 * kNativeCount) {
      return_now_ = run_native((func1 - kNativeFuncs) / 4);
      continue;
    }
    if (func1) {
      call_guest(func1, 0, {Resume::kChainFunc1, func2, 1});
      return;
    }
  }
  // A non-interrupt exception that reached no handler of the program's.
  if (unresolved_) {
    fail_exception();
    return;
  }
  // All chains done: longjmp through the exit buffer with v0 = 1 (ra, sp, fp, s0-s7, gp).
  book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kChainExit);
  dispatching_ = false;
  u32 b = exit_buf_;
  cpu_.set_reg(kSp, peek32(b + 4));
  cpu_.set_reg(kFp, peek32(b + 8));
  for (u32 i = 0; i < 8; ++i) cpu_.set_reg(16 + i, peek32(b + 12 + 4 * i));
  cpu_.set_reg(kGp, peek32(b + 44));
  cpu_.set_reg(kV0, 1);
  cpu_.set_pc(peek32(b));
}

void HleBios::call_guest(u32 func, u32 a0, Resume r) {
  resume_.push_back(r);
  cpu_.set_reg(kA0r, a0);
  cpu_.set_reg(kRa, kReturnStub);
  // Interrupt handlers run on the kernel's exception stack, like the BIOS's.
  if (r.in_dispatch) cpu_.set_reg(kSp, kExceptionStack);
  cpu_.set_pc(func);
}

void HleBios::guest_returned() {
  if (resume_.empty()) {
    if (on_fatal) on_fatal("HLE kernel: the return stub ran with no kernel call pending");
    cpu_.stop();
    return;
  }
  Resume r = resume_.back();
  resume_.pop_back();
  u32 v0 = cpu_.reg(kV0);
  switch (r.kind) {
    case Resume::kChainFunc1:
      if (v0 && r.value) {
        call_guest(r.value, v0, {Resume::kDispatch, 0, 1});
        return;
      }
      dispatch_next();
      return;
    case Resume::kDispatch: dispatch_next(); return;
    case Resume::kSearch: comparison_returned(static_cast<s32>(v0)); return;
    case Resume::kCaller:
      if (!callbacks_.empty()) {
        u32 f = callbacks_.front();
        callbacks_.erase(callbacks_.begin());
        call_guest(f, 0, r);
        return;
      }
      cpu_.set_reg(kRa, r.value);
      cpu_.set_pc(r.value);
      return;
  }
}

bool HleBios::run_native(u32 id) {
  switch (id) {
    case kRcntVblank: return rcnt_handler(3);
    case kRcnt2: return rcnt_handler(2);
    case kRcnt1: return rcnt_handler(1);
    case kRcnt0: return rcnt_handler(0);
    case kPad: return pad_handler();
    case kDefInt: return def_int();
    case kSyscallHandler: return unresolved_exception();
    default: return false;
  }
}

// The syscall handler's part for other exceptions (SYSCALL never reaches the chains here): for
// anything but an interrupt it delivers F0000010h/1000h, then calls A0h:40h
// SystemErrorUnresolvedException through the A table (psx-spx "BIOS Interrupt/Exception
// Handling"; OpenBIOS handlers/syscall.c, syscallVerifier). Programs replace that entry to
// resolve exceptions themselves (ps1-tests' hookUnresolvedExceptionHandler edits the TCB's EPC
// and returns); the walk then goes on and the exit buffer resumes the program. The kernel's own
// entry shows the error and hangs on a BIOS: here the console stops, once the event's
// callbacks have run (one may return from the exception instead).
bool HleBios::unresolved_exception() {
  if (!unresolved_) {
    book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kHandlerMiss);
    return false;
  }
  deliver_event(0xF0000010, 0x1000);
  u32 entry = peek32(kTableA + 4 * 0x40);
  if (entry == kStubs + 8 * 0x40) {
    chain_prio_ = 3;  // ends the walk: dispatch_next() stops the console after the callbacks
    chain_elem_ = 0;
    return false;
  }
  unresolved_ = false;
  callbacks_.push_back(entry);
  return false;
}

// DefInt: an event per pending IRQ (IRQ6, timer 2, uses timer 1's class, as the BIOS does:
// psx-spx "BIOS Event Summary"), acknowledging those SetIrqAutoAck turned on.
bool HleBios::def_int() {
  static constexpr u32 kClass[11] = {1, 2, 3, 4, 5, 6, 6, 8, 0xB, 9, 0xA};
  book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kDefInt);
  for (u32 i = 0; i < 11; ++i) {
    if (!(io_read(kIStat, 4) & io_read(kIMask, 4) & (1u << i))) continue;
    book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kDeliverEvent);
    deliver_event(0xF0000000 | kClass[i], 0x1000);
    if (irq_auto_ack_ & (1u << i)) io_write(kIStat, ~(1u << i) & 0xFFFF, 4);
  }
  return false;
}

// Root counter t: deliver F200000th/0002h; with ChangeClearRCnt on, acknowledge the IRQ and
// leave the exception at once. Root counter 3 is the VBlank IRQ (psx-spx "BIOS Timer Functions";
// OpenBIOS's handlers test IRQ0 for it too).
bool HleBios::rcnt_handler(u32 t) {
  u32 bit = t == 3 ? 1u : 1u << (4 + t);
  if (!(io_read(kIStat, 4) & io_read(kIMask, 4) & bit)) {
    book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kHandlerMiss);
    return false;
  }
  book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kRcntHit + hle_cost::kDeliverEvent);
  deliver_event(0xF2000000 | t, 0x0002);
  if (!clear_rcnt_[t]) return false;
  io_write(kIStat, ~bit & 0xFFFF, 4);
  return true;
}

// PadCardIrq: at VBlank, both pads are read into the InitPad buffers (status, ID, data); with
// ChangeClearPad on, the VBlank IRQ is acknowledged and the walk goes on to the lower chains, as
// OpenBIOS's pad handler does (sio0/driver.c, sio0Handler: it never returns from the exception).
bool HleBios::pad_handler() {
  if (!(io_read(kIStat, 4) & io_read(kIMask, 4) & 1)) {
    book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kHandlerMiss);
    return false;
  }
  book(sched_, peek32(current_tcb() + kTcbCause), hle_cost::kPadPoll);
  for (int port = 0; port < 2; ++port)
    if (pad_buf_[port]) read_pad(port, pad_buf_[port]);
  if (clear_pad_) io_write(kIStat, 0xFFFE, 4);
  return false;
}

// One "read" command (01h 42h 00h...) straight to the controller (psx-spx "Controllers -
// Communication Sequence"); the buffer holds up to 22h bytes.
void HleBios::read_pad(int port, u32 buf) {
  SioDevice* dev = pad_at ? pad_at(port) : nullptr;
  if (!dev) {
    poke8(buf, 0xFF);
    return;
  }
  dev->deselect();
  SioDevice::Reply r = dev->transfer(0x01);
  if (!r.ack) {
    dev->deselect();
    poke8(buf, 0xFF);
    return;
  }
  SioDevice::Reply id = dev->transfer(0x42);
  SioDevice::Reply idhi = dev->transfer(0x00);
  poke8(buf, idhi.data == 0x5A ? 0x00 : 0xFF);
  poke8(buf + 1, id.data);
  r = idhi;
  for (u32 i = 2; i < 0x22 && r.ack; ++i) {
    r = dev->transfer(0x00);
    poke8(buf + i, r.data);
  }
  dev->deselect();
}

// An element already in the chain is moved to its head rather than linked twice (which would
// loop the chain forever).
void HleBios::enqueue(u32 prio, u32 elem) {
  dequeue(prio, elem);
  poke32(elem, chain_head(prio));
  set_chain_head(prio, elem);
}

void HleBios::dequeue(u32 prio, u32 elem) {
  if (chain_head(prio) == elem) {
    set_chain_head(prio, peek32(elem));
    return;
  }
  for (u32 e = chain_head(prio), n = 0; e && n < 256; e = peek32(e), ++n)
    if (peek32(e) == elem) {
      poke32(e, peek32(elem));
      return;
    }
}

bool HleBios::interrupt_call(u32 table, u32 fn) {
  const u32 a0 = cpu_.reg(kA0r), a1 = cpu_.reg(kA1);
  if (table == kC0) {
    switch (fn) {
      case 0x02: enqueue(a0, a1); return_to_caller(0); return true;  // SysEnqIntRP
      case 0x03: dequeue(a0, a1); return_to_caller(0); return true;  // SysDeqIntRP
      case 0x00: {  // EnqueueTimerAndVblankIrqs: the four root counter handlers, counters stopped
        io_write(kIMask, io_read(kIMask, 4) & ~0x71u, 4);
        clear_rcnt_ = {1, 1, 1, 1};
        for (u32 id : {kRcnt0, kRcnt1, kRcnt2, kRcntVblank}) enqueue(a0, kKernelElems + 16 * id);
        for (u32 t = 0; t < 3; ++t)
          for (u32 r : {4u, 8u, 0u}) io_write(0xBF801100 + 16 * t + r, 0, 2);
        return_to_caller(1);
        return true;
      }
      case 0x01: enqueue(a0, kKernelElems + 16 * kSyscallHandler); return_to_caller(1); return true;
      case 0x0C:  // InitDefInt: DefInt with every auto-acknowledge off
        irq_auto_ack_ = 0;
        enqueue(a0, kKernelElems + 16 * kDefInt);
        return_to_caller(1);
        return true;
      case 0x0D:  // SetIrqAutoAck(irq, flag)
        if (a0 < 11) irq_auto_ack_ = a1 ? irq_auto_ack_ | (1u << a0) : irq_auto_ack_ & ~(1u << a0);
        return_to_caller(0);
        return true;
      case 0x0A: {                                                   // ChangeClearRCnt
        u32 old = clear_rcnt_[a0 & 3];
        clear_rcnt_[a0 & 3] = a1 ? 1 : 0;
        return_to_caller(old);
        return true;
      }
      default: return false;
    }
  }
  // The SDKs pass a counter's event class (F200000xh, "RCntCNTx"); the kernel uses its low 16
  // bits (OpenBIOS handlers/irq.c: initTimer, enableTimerIRQ, disableTimerIRQ, restartTimer;
  // its getTimer takes the number as it is).
  const u32 t = a0 & 0xFFFF, base = 0xBF801100 + 16 * t;
  switch (fn) {
    case 0x02: {  // SetRCnt (init_timer): mode from the flags, psx-spx "BIOS Timer Functions"
      if (t > 2) {
        return_to_caller(0);
        return true;
      }
      u32 mode = (cpu_.reg(6) & 0x10) ? 0x49 : 0x48;
      if (!(cpu_.reg(6) & 1)) mode |= 0x100;
      if (cpu_.reg(6) & 0x1000) mode |= 0x10;
      io_write(base + 4, 0, 2);
      io_write(base + 8, a1, 2);
      io_write(base + 4, mode, 2);
      return_to_caller(1);
      return true;
    }
    case 0x03: return_to_caller(a0 <= 2 ? io_read(base, 2) : 0); return true;  // GetRCnt
    case 0x04:                                                                 // StartRCnt
      io_write(kIMask, io_read(kIMask, 4) | (t == 3 ? 1u : 1u << (4 + (t & 3))), 4);
      return_to_caller(t <= 2 ? 1 : 0);
      return true;
    case 0x05:  // StopRCnt
      io_write(kIMask, io_read(kIMask, 4) & ~(t == 3 ? 1u : 1u << (4 + (t & 3))), 4);
      return_to_caller(1);
      return true;
    case 0x06:  // ResetRCnt
      if (t <= 2) io_write(base, 0, 2);
      return_to_caller(t <= 2 ? 1 : 0);
      return true;
    case 0x12:  // InitPad(buf1, siz1, buf2, siz2): remember and zero-fill the buffers
      pad_buf_ = {a0, cpu_.reg(6)};
      for (u32 i = 0; i < a1 && i < 0x22; ++i) poke8(a0 + i, 0);
      for (u32 i = 0; i < cpu_.reg(7) && i < 0x22; ++i) poke8(cpu_.reg(6) + i, 0);
      return_after(2, hle_cost::kInitPad);
      return true;
    case 0x13:  // StartPad: enqueue the pad handler, VBlank IRQ acknowledged and on, and the
      // VBlank root counter handler no longer ends the exception before the pad handler runs
      // (ChangeClearRCnt(3,0)) while the pad handler acknowledges (ChangeClearPad(1)), as
      // OpenBIOS's startPad does (sio0/driver.c) and Sony's libraries do after enqueueing their
      // own pad handler.
      if (!pad_started_) enqueue(2, kKernelElems + 16 * kPad);
      pad_started_ = true;
      clear_rcnt_[3] = 0;
      clear_pad_ = 1;
      io_write(kIStat, 0xFFFE, 4);
      io_write(kIMask, io_read(kIMask, 4) | 1, 4);
      return_after(1, hle_cost::kStartPad);
      return true;
    case 0x14:  // StopPad: the pad handler out, VBlank auto-acknowledge back on (stopPad)
      if (pad_started_) dequeue(2, kKernelElems + 16 * kPad);
      pad_started_ = false;
      clear_rcnt_[3] = 1;
      return_to_caller(1);
      return true;
    case 0x17: return_from_exception(); return true;
    case 0x18: exit_buf_ = kDefaultExit; return_to_caller(kDefaultExit); return true;  // ResetEntryInt
    case 0x19: exit_buf_ = a0; return_to_caller(0); return true;                     // HookEntryInt
    case 0x5B: clear_pad_ = a0 ? 1 : 0; return_to_caller(0); return true;            // ChangeClearPad
    default: return false;
  }
}

}  // namespace psx
