// Test harness for the CD-ROM controller: a scheduler, interrupt controller and audio FIFO around
// one Cdrom, driven through its registers as a program would (psx-spx "CDROM Controller I/O").
#pragma once
#include <gtest/gtest.h>

#include <vector>

#include "core/cdrom/cdrom.h"

namespace psx::test {

struct CdResponse {
  u8 irq = 0;
  std::vector<u8> bytes;
  Cycles at = 0;
};

class CdromHarness {
 public:
  Scheduler sched;
  InterruptController irq;
  Cdrom cd{sched, irq};
  AudioFifo& fifo = cd.audio_out();

  CdromHarness() {
    cd.io_write(0, 1, 1);
    cd.io_write(2, 0x1F, 1);  // enable INT1-INT5
    irq.write(4, 1u << static_cast<u32>(Irq::Cdrom));
  }

  void send(u8 cmd, std::vector<u8> params = {}) {
    cd.io_write(0, 0, 1);
    for (u8 p : params) cd.io_write(2, p, 1);
    cd.io_write(1, cmd, 1);
  }

  // Runs the scheduler until the CD-ROM raises its interrupt line (or `max` cycles pass), reads
  // the flag and the whole response, and acknowledges both the controller and the line.
  CdResponse wait(Cycles max = 200'000'000, bool ack = true) {
    const Cycles end = sched.now() + max;
    while (!(irq.stat() & 4u)) {
      Cycles next = sched.next_deadline();
      if (next == Scheduler::kNever || next > end) return {};
      sched.advance(next - sched.now());
      sched.run_due_events();
    }
    CdResponse r;
    r.at = sched.now();
    cd.io_write(0, 1, 1);
    r.irq = cd.io_read(3, 1) & 7;
    cd.io_write(0, 0, 1);
    // The response FIFO holds 16 bytes: HSTS.5 (not empty) must clear after at most 16 reads.
    while ((cd.io_read(0, 1) & 0x20) && r.bytes.size() < 16) r.bytes.push_back(static_cast<u8>(cd.io_read(1, 1)));
    if (cd.io_read(0, 1) & 0x20) ADD_FAILURE() << "HSTS.5 still shows response bytes after 16 reads";
    if (ack) acknowledge();
    return r;
  }

  void acknowledge() {
    cd.io_write(0, 1, 1);
    cd.io_write(3, 0x1F, 1);
    cd.io_write(0, 0, 1);
    irq.write(0, ~(1u << static_cast<u32>(Irq::Cdrom)));
  }

  // Runs the timeline forward by `n` cycles without stopping at interrupts.
  void run_for(Cycles n) {
    const Cycles end = sched.now() + n;
    while (sched.next_deadline() <= end) {
      sched.advance(sched.next_deadline() - sched.now());
      sched.run_due_events();
    }
    sched.advance(end - sched.now());
  }

  std::vector<u8> read_data(u32 n) {
    cd.io_write(0, 0, 1);
    cd.io_write(3, 0x80, 1);  // BFRD: sector buffer -> data FIFO
    std::vector<u8> out;
    for (u32 i = 0; i < n; ++i) out.push_back(static_cast<u8>(cd.io_read(2, 1)));
    return out;
  }
};

inline std::vector<u8> bytes(std::initializer_list<u8> b) { return b; }

}  // namespace psx::test
