// HLE kernel: BIOS events (psx-spx "BIOS Event Functions"): event control blocks opened with a
// class/spec pair and a mode, delivered by the kernel's interrupt handlers or by the program.
// Mode 2000h marks a delivered event ready (TestEvent/WaitEvent consume it); mode 1000h calls
// the event's function instead and leaves it busy.
#include "core/bios/hle_bios.h"

namespace psx {

namespace {
constexpr u32 kA0r = 4, kA1 = 5, kA2 = 6, kA3 = 7, kRa = 31;
constexpr u32 kHandleBase = 0xF1000000;
constexpr u32 kFree = 0, kDisabled = 0x1000, kBusy = 0x2000, kReady = 0x4000;
constexpr u32 kModeCallback = 0x1000, kModeReady = 0x2000;
// EvCB layout: class, status, spec, mode, function, two unused words (1Ch bytes).
constexpr u32 kClass = 0x00, kStatus = 0x04, kSpec = 0x08, kMode = 0x0C, kFunc = 0x10;
constexpr u32 kEvcbPtr = 0x80000120;  // the table of tables' EvCB pointer; its size follows
}  // namespace

// The address of an open event's EvCB, 0 for a bad or closed handle.
u32 HleBios::event_at(u32 handle) const {
  u32 i = handle - kHandleBase, base = peek32(kEvcbPtr);
  if (i >= peek32(kEvcbPtr + 4) / kEvcbSize) return 0;
  u32 e = base + i * kEvcbSize;
  return peek32(e + kStatus) == kFree ? 0 : e;
}

void HleBios::deliver_event(u32 cls, u32 spec) {
  u32 base = peek32(kEvcbPtr), n = peek32(kEvcbPtr + 4) / kEvcbSize;
  for (u32 i = 0; i < n && i < 256; ++i) {
    u32 e = base + i * kEvcbSize;
    if (peek32(e + kStatus) != kBusy || peek32(e + kClass) != cls || peek32(e + kSpec) != spec) continue;
    u32 mode = peek32(e + kMode), func = peek32(e + kFunc);
    if (mode == kModeReady) poke32(e + kStatus, kReady);
    else if (mode == kModeCallback && func) callbacks_.push_back(func);
  }
}

bool HleBios::event_call(u32 fn) {
  const u32 a0 = cpu_.reg(kA0r), a1 = cpu_.reg(kA1);
  switch (fn) {
    case 0x07:  // DeliverEvent: callbacks run before returning to the caller
      deliver_event(a0, a1);
      if (callbacks_.empty()) {
        return_to_caller(0);
      } else {
        u32 f = callbacks_.front();
        callbacks_.erase(callbacks_.begin());
        call_guest(f, 0, {Resume::kCaller, cpu_.reg(kRa), 0});
      }
      return true;
    case 0x08: {  // OpenEvent(class, spec, mode, func): starts disabled
      u32 base = peek32(kEvcbPtr), n = peek32(kEvcbPtr + 4) / kEvcbSize;
      for (u32 i = 0; i < n && i < 256; ++i) {
        u32 e = base + i * kEvcbSize;
        if (peek32(e + kStatus) != kFree) continue;
        poke32(e + kClass, a0), poke32(e + kSpec, a1), poke32(e + kMode, cpu_.reg(kA2));
        poke32(e + kFunc, cpu_.reg(kA3)), poke32(e + kStatus, kDisabled);
        return_to_caller(kHandleBase + i);
        return true;
      }
      return_to_caller(0xFFFFFFFF);
      return true;
    }
    case 0x09:  // CloseEvent
      if (u32 e = event_at(a0)) poke32(e + kStatus, kFree);
      return_to_caller(1);
      return true;
    case 0x0A: {  // WaitEvent: 0 when disabled, else waits until ready and consumes it
      u32 e = event_at(a0), status = e ? peek32(e + kStatus) : kFree;
      if (!e || status == kDisabled) {
        return_to_caller(0);
      } else if (status == kReady) {
        poke32(e + kStatus, kBusy);
        return_to_caller(1);
      } else {
        cpu_.set_pc(kRetryB0);  // spins through B0h with t1 = 0Ah; interrupts stay enabled
      }
      return true;
    }
    case 0x0B: {  // TestEvent
      u32 e = event_at(a0);
      bool ready = e && peek32(e + kStatus) == kReady;
      if (ready) poke32(e + kStatus, kBusy);
      return_to_caller(ready ? 1 : 0);
      return true;
    }
    case 0x0C:  // EnableEvent
      if (u32 e = event_at(a0); e && peek32(e + kStatus) == kDisabled) poke32(e + kStatus, kBusy);
      return_to_caller(1);
      return true;
    case 0x0D:  // DisableEvent
      if (u32 e = event_at(a0)) poke32(e + kStatus, kDisabled);
      return_to_caller(1);
      return true;
    case 0x20: {  // UnDeliverEvent: ready events of mode 2000h with this class/spec become busy
      u32 base = peek32(kEvcbPtr), n = peek32(kEvcbPtr + 4) / kEvcbSize;
      for (u32 i = 0; i < n && i < 256; ++i) {
        u32 e = base + i * kEvcbSize;
        if (peek32(e + kStatus) == kReady && peek32(e + kMode) == kModeReady && peek32(e + kClass) == a0 &&
            peek32(e + kSpec) == a1)
          poke32(e + kStatus, kBusy);
      }
      return_to_caller(0);
      return true;
    }
    default: return false;
  }
}

}  // namespace psx
