// DMA controller (psx-spx "DMA Channels"): seven channels at 0x1F801080 + N*0x10 (MADR, BCR,
// CHCR), DPCR (priorities and enables) at 0x1F8010F0 and DICR (interrupts) at 0x1F8010F4.
// Channels 0-4 move words between main RAM and a device (MDECin, MDECout, GPU, CD-ROM, SPU)
// through its DmaPort; channel 5 (PIO) has no device here; channel 6 (OTC) builds the GPU's
// reversed ordering table in RAM. The CPU is held while the controller owns the bus: every moved
// word is charged to the scheduler at the documented per-channel rate. Between sync mode 1 blocks,
// chopping windows and linked-list nodes the bus goes back to the CPU; the channel's next turn is
// booked on the scheduler (Channel::resume_at, the "dma" event).
#pragma once
#include <array>
#include <vector>

#include "core/io_device.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class Bus;
class InterruptController;

class Dma : public IoDevice {
 public:
  static constexpr u32 kBase = 0x1F801080;
  static constexpr u32 kSize = 0x80;
  static constexpr u32 kChannels = 7;
  enum ChannelId : u32 { MdecIn = 0, MdecOut = 1, Gpu = 2, Cdrom = 3, Spu = 4, Pio = 5, Otc = 6 };

  Dma(Scheduler& sched, InterruptController& irq, Bus& bus);

  // Attaches the device side of channels 0-4 (null detaches it).
  void connect(u32 channel, DmaPort* port);

  u32 io_read(u32 offset, u32 width) override;
  void io_write(u32 offset, u32 value, u32 width) override;

  u32 madr(u32 ch) const { return channels_[ch].madr; }
  u32 bcr(u32 ch) const { return channels_[ch].bcr; }
  u32 chcr(u32 ch) const { return channels_[ch].chcr; }
  u32 dicr() const { return dicr_; }

  void do_state(StateIO& s);

  // D#_CHCR bits.
  static constexpr u32 kChcrFromRam = 1u << 0;
  static constexpr u32 kChcrBackward = 1u << 1;
  static constexpr u32 kChcrChopping = 1u << 8;
  static constexpr u32 kChcrBusy = 1u << 24;
  static constexpr u32 kChcrTrigger = 1u << 28;
  // Linked-list end: any node address with bit 23 set ends the list, but only 0x00FFFFFF ends it
  // cleanly; any other sets DICR bit 15 (pcsx-redux src/mips/tests/dma, run on hardware).
  static constexpr u32 kListEnd = 0x00FFFFFF;
  // DICR bit 15: the bus error flag, read/write, which forces bit 31 while set (psx-spx).
  static constexpr u32 kDicrBusError = 1u << 15;

 private:
  struct Channel {
    u32 madr = 0;
    u32 bcr = 0;
    u32 chcr = 0;
    // Sync mode 0 with chopping: the transfer has begun and continues after each CPU window.
    bool chopping_started = false;
    // Earliest time the channel may move its next block or window (the CPU runs until then).
    Cycles resume_at = 0;

    u32 sync_mode() const { return (chcr >> 9) & 3; }
  };

  void write_channel(u32 ch, u32 reg, u32 value);
  void write_dicr(u32 value);
  // Recomputes DICR bit 31 and raises IRQ3 on its 0-to-1 edge.
  void update_master_flag();

  bool enabled(u32 ch) const { return (dpcr_ >> (ch * 4 + 3)) & 1; }
  u32 priority(u32 ch) const { return (dpcr_ >> (ch * 4)) & 7; }
  bool device_request(u32 ch) const;
  bool may_run(u32 ch) const;
  // The channel to run next among `candidates` (a bit per channel), or -1.
  int pick_channel(u32 candidates) const;

  // Runs every channel that may run, highest priority first, within one bounded slice of words,
  // then books the event that continues or polls the ones still waiting.
  void service(Cycles late = 0);
  // One unit of work on a channel; returns the words moved.
  u32 run_burst(u32 ch);
  u32 run_block(u32 ch);
  // One node of a linked list; more, up to `budget` words and a batch of nodes, while the channel
  // is the only candidate (`alone`) and may still run: service() would pick it again.
  u32 run_list(u32 ch, u32 budget, bool alone);
  u32 run_otc(u32 ch);
  void finish(u32 ch);

  // RAM <-> device word movement (addresses step by +-4 and wrap in RAM).
  void to_device(u32 ch, u32 addr, u32 count, bool backward);
  void from_device(u32 ch, u32 addr, u32 count, bool backward);
  // Holds the CPU for `words` at the channel's rate plus `extra_per256` clocks per 0x100 words.
  void charge(u32 ch, u32 words, u32 extra_per256 = 0);
  // The channel's rate in CPU clocks per 0x100 words.
  u64 clocks_per256_words(u32 ch) const;
  // Holds the CPU for `cycles256` / 256 cycles (the remainder carries over to the next charge).
  void charge_cycles256(u64 cycles256);

  Scheduler& sched_;
  InterruptController& irq_;
  Bus& bus_;
  std::array<DmaPort*, kChannels> ports_{};
  std::array<Channel, kChannels> channels_{};
  u32 dpcr_ = 0x07654321;  // reset value (psx-spx)
  u32 dicr_ = 0;
  Scheduler::Handle event_;
  // Transfer staging buffer (not state: always empty between transfers).
  std::vector<u32> words_;
  // Charge remainder in 1/256 cycles, so rates such as 0x110 clocks per 0x100 words stay exact.
  u32 charge_frac_ = 0;
  // Cycles the CPU ran past the event's booking, not yet set against a charge (not state: zero
  // outside service()).
  Cycles late_credit_ = 0;
};

}  // namespace psx
