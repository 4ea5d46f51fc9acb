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
}  // namespace

HleBios::Event* HleBios::event_at(u32 handle) {
  u32 i = handle - kHandleBase;
  if (i >= kMaxEvents || events_[i].status == kFree) return nullptr;
  return &events_[i];
}

void HleBios::deliver_event(u32 cls, u32 spec) {
  for (Event& e : events_) {
    if (e.status != kBusy || e.cls != cls || e.spec != spec) continue;
    if (e.mode == kModeReady) e.status = kReady;
    else if (e.mode == kModeCallback && e.func) callbacks_.push_back(e.func);
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
      for (u32 i = 0; i < kMaxEvents; ++i) {
        if (events_[i].status != kFree) continue;
        events_[i] = {a0, a1, cpu_.reg(kA2), cpu_.reg(kA3), kDisabled};
        return_to_caller(kHandleBase + i);
        return true;
      }
      return_to_caller(0xFFFFFFFF);
      return true;
    }
    case 0x09:  // CloseEvent
      if (Event* e = event_at(a0)) e->status = kFree;
      return_to_caller(1);
      return true;
    case 0x0A: {  // WaitEvent: 0 when disabled, else waits until ready and consumes it
      Event* e = event_at(a0);
      if (!e || e->status == kDisabled) {
        return_to_caller(0);
      } else if (e->status == kReady) {
        e->status = kBusy;
        return_to_caller(1);
      } else {
        cpu_.set_pc(kRetryB0);  // spins through B0h with t1 = 0Ah; interrupts stay enabled
      }
      return true;
    }
    case 0x0B: {  // TestEvent
      Event* e = event_at(a0);
      bool ready = e && e->status == kReady;
      if (ready) e->status = kBusy;
      return_to_caller(ready ? 1 : 0);
      return true;
    }
    case 0x0C:  // EnableEvent
      if (Event* e = event_at(a0); e && e->status == kDisabled) e->status = kBusy;
      return_to_caller(1);
      return true;
    case 0x0D:  // DisableEvent
      if (Event* e = event_at(a0)) e->status = kDisabled;
      return_to_caller(1);
      return true;
    case 0x20:  // UnDeliverEvent: ready events of mode 2000h with this class/spec become busy
      for (Event& e : events_)
        if (e.status == kReady && e.mode == kModeReady && e.cls == a0 && e.spec == a1) e.status = kBusy;
      return_to_caller(0);
      return true;
    default: return false;
  }
}

}  // namespace psx
