// DMA controller: register interface, channel arbitration and the three sync modes.
#include "core/dma.h"

#include <algorithm>
#include <bit>

#include "core/bus.h"
#include "core/irq.h"

namespace psx {

namespace {
// Transfer rates in CPU clocks per 0x100 words (psx-spx "DMA Transfer Rates"; DMA uses DRAM hyper
// page mode, one clock a word plus a row reload every 16 words). PIO moves no data here but still
// takes its documented time. The CD-ROM entry is not used: see charge().
constexpr std::array<u32, Dma::kChannels> kClocksPer256Words = {0x110, 0x110, 0x110, 0x1800,
                                                                 0x420, 0x1400, 0x110};
// Words one service pass may move before the controller lets the scheduler dispatch other events;
// it keeps a guest's endless linked list or 0xFFFF x 0xFFFF block transfer from stalling the host.
constexpr u32 kSliceWords = 0x10000;
// How often a channel waiting for its device's DMA request looks again.
constexpr Cycles kRequestPollCycles = 64;
// Sync mode 1 and chopping hand the bus back to the CPU between blocks and windows. The figures
// below are fitted to ps1-tests `dma/chopping`, GPU DMA timed on two consoles
// (tests/data/ps1-tests/dma-chopping*.log): 8192 bytes take 2196 cycles in one burst, 22,819 in
// 1-word blocks, 2471 in 128-word blocks. With these rules that program, run here, comes within
// 3.9% of the later run for every block size and 2.4% for every window pair but two
// (docs/fidelity.md); the two runs differ from each other by up to 6.1% (blocks), 0.9% (pairs).
// Both gaps count from the end of the block or window on the controller's own time: the CPU's
// instruction under way then finishes beside the controller (service()'s late credit) and does
// not push the next turn back.
// Sync mode 1: after each block the controller releases the bus for 10 cycles before it serves
// the device's next request (the CPU runs meanwhile), and a block's words cost 0x120 clocks per
// 0x100 (one more clock per 16 words than a burst at the GPU's 0x110).
constexpr Cycles kBlockGapCycles = 10;
constexpr u32 kBlockExtraPer256Words = 0x10;
// Chopping: the CPU window of 1 << N clocks (CHCR bits 20-22) is followed by 6 more before the
// next DMA window starts; a window of 1 word, 1 clock took 8.15 cycles a word, 1 word, 128 clocks
// 135.1.
constexpr Cycles kChopGapCycles = 6;
// Sync mode 2: after each node the bus goes back to the CPU for the same 6 cycles as after a
// chopping window. The header read holds it for 3.59 cycles (0x398/256): with those two, CPU work
// takes 9.59/6 = 1.598 times as long while an endless list of empty nodes runs, as ps1-tests
// `dma/chain-looping` measured on the console (16040 cycles alone, 25632 and 25640 beside a list
// of one and of two self-linked empty nodes). A node with words spends 5 more cycles before them:
// Mednafen charges 15 clocks for such a header against 10 for an empty one, DuckStation 8 + 5.
// These are fits and other emulators' figures, not psx-spx's (it gives no node cost).
constexpr Cycles kListGapCycles = kChopGapCycles;
constexpr u64 kListHeader256 = 0x398;
constexpr u64 kListPayloadSetup256 = 5 * 256;
// Nodes walked before the CPU is given their gaps: 128 empty nodes hold the CPU for 460 cycles,
// then it runs for 768. The instruction under way when a batch starts finishes beside it
// (service()'s late credit), so smaller batches give the CPU more than its share (chain-looping's
// loop takes 1.48 times as long with 8 nodes, 1.58 with 32, 1.60 with 128; the console 1.598),
// and cost more host time (Tumble's demo, recompiler: 32 nodes +17% host instructions, 128 +5%).
constexpr u32 kListBatchNodes = 128;
constexpr u32 kAddressMask = 0x00FFFFFC;  // updated addresses are word aligned (psx-spx)

constexpr u32 count_or_max(u32 v) { return v == 0 ? 0x10000 : v; }  // 0 means 0x10000
}  // namespace

Dma::Dma(Scheduler& sched, InterruptController& irq, Bus& bus) : sched_(sched), irq_(irq), bus_(bus) {
  event_ = sched_.add_event("dma", [this](Cycles late) { service(late); });
  channels_[Otc].chcr = kChcrBackward;  // D6_CHCR bit 1 always reads 1
}

void Dma::connect(u32 channel, DmaPort* port) {
  if (channel < Pio) ports_[channel] = port;
}

u32 Dma::io_read(u32 offset, u32 width) {
  u32 reg = offset & ~3u;
  u32 shift = (offset & 3) * 8;
  u32 v = 0;
  if (reg < 0x70) {
    const Channel& c = channels_[reg >> 4];
    switch (reg & 0xC) {
      case 0x0: v = c.madr; break;
      case 0x4: v = c.bcr; break;
      case 0x8: v = c.chcr; break;
      default: v = 0; break;
    }
  } else {
    switch (reg) {
      case 0x70: v = dpcr_; break;
      case 0x74: v = dicr_; break;
      case 0x78: v = 0x7FFAC68B; break;  // undocumented read-only values (psx-spx)
      default: v = 0x00FFFFF7; break;
    }
  }
  return v >> shift;
}

// Every register here is 32 bits wide and the bus hands each CPU store over whole (an SB or SH
// drives the full register value, Bus::io_write()), so `value` is the register's new value.
void Dma::io_write(u32 offset, u32 value, u32 /*width*/) {
  const u32 reg = offset & ~3u;
  if (reg < 0x70) {
    write_channel(reg >> 4, reg & 0xC, value);
  } else if (reg == 0x70) {
    dpcr_ = value;
    service();
  } else if (reg == 0x74) {
    write_dicr(value);
  }
}

void Dma::write_channel(u32 ch, u32 reg, u32 value) {
  Channel& c = channels_[ch];
  switch (reg) {
    case 0x0: c.madr = value & 0x00FFFFFF; return;
    case 0x4: c.bcr = value; return;
    case 0x8: break;
    default: return;
  }
  bool was_busy = c.chcr & kChcrBusy;
  // D6_CHCR: only bits 24, 28 and 30 are writable; bit 1 (step backward) always reads 1.
  c.chcr = ch == Otc ? (value & 0x51000000) | kChcrBackward : value & 0x71770703;
  if (!(c.chcr & kChcrBusy)) c.chopping_started = false;  // the CPU stopped the channel
  if (!was_busy && (c.chcr & kChcrBusy)) c.resume_at = 0;
  service();
}

// DICR (psx-spx "DMA Interrupt Register"): bits 0-5 read/write, 6-14 always zero, 15 bus error
// (read/write: a linked list's unclean end sets it, the CPU may set or clear it; it forces IRQ),
// 16-22 per-channel enables, 23 master enable; writing 1 to a flag (24-30) clears it.
void Dma::write_dicr(u32 value) {
  u32 ack = value & 0x7F000000;
  dicr_ = (dicr_ & 0xFF000000 & ~ack) | (value & 0x00FF803F);
  update_master_flag();
}

// Bit 31 = bit 15 OR (bit 23 AND any flag in 24-30). The per-channel enables only gate whether a
// finishing channel sets its flag (finish()), so re-enabling bit 23 while a flag is still pending
// raises bit 31 again even with every channel enable clear. I_STAT bit 3 fires on its 0-to-1 edge.
void Dma::update_master_flag() {
  bool before = dicr_ >> 31;
  bool after = (dicr_ & (1u << 15)) || ((dicr_ & (1u << 23)) && (dicr_ & 0x7F000000));
  dicr_ = (dicr_ & 0x7FFFFFFF) | (after ? 0x80000000u : 0);
  if (after && !before) irq_.raise(Irq::Dma);
}

bool Dma::device_request(u32 ch) const {
  // OTC has no device to request: it runs only when started with Start/Trigger (bit 28). On the
  // console CHCR = 01000002h leaves RAM untouched (ps1-tests dma/otc-test,
  // testOtcWontStartOnAutomaticMode; Mednafen's notes: "DMA hangs if D28 of CHCR is 0").
  if (ch == Otc) return false;
  return ports_[ch] && ports_[ch]->dma_request();
}

bool Dma::may_run(u32 ch) const {
  const Channel& c = channels_[ch];
  if (!(c.chcr & kChcrBusy) || !enabled(ch) || sched_.now() < c.resume_at) return false;
  if (c.chopping_started) return true;
  // Start/Trigger starts sync mode 0, and forces one block of the others without a request.
  return (c.chcr & kChcrTrigger) || device_request(ch);
}

int Dma::pick_channel(u32 candidates) const {
  // Lowest DPCR priority value wins; on a tie the higher channel number wins (psx-spx).
  int best = -1;
  for (; candidates != 0; candidates &= candidates - 1) {
    const u32 ch = static_cast<u32>(std::countr_zero(candidates));  // ascending, for the tie rule
    if (may_run(ch) && (best < 0 || priority(ch) <= priority(static_cast<u32>(best)))) best = static_cast<int>(ch);
  }
  return best;
}

void Dma::service(Cycles late) {
  // The controller takes the bus at its booked time, mid-instruction if need be; the CPU can only
  // be stopped between instructions, so the cycles it ran past the booking are counted as the
  // first block's own (otherwise every window would end up to an instruction's length late).
  late_credit_ = late;
  // Only busy, enabled channels may run, and during a slice no channel becomes either (only CPU
  // writes to CHCR and DPCR do that), so the others need not be asked for each list node.
  u32 candidates = 0;
  for (u32 c = 0; c < kChannels; ++c)
    if ((channels_[c].chcr & kChcrBusy) && enabled(c)) candidates |= 1u << c;
  u32 budget = kSliceWords;
  int ch;
  while (budget > 0 && (ch = pick_channel(candidates)) >= 0) {
    u32 c = static_cast<u32>(ch);
    u32 moved;
    if (c == Otc) moved = run_otc(c);
    else if (channels_[c].sync_mode() == 1) moved = run_block(c);
    else if (channels_[c].sync_mode() == 2) moved = run_list(c, budget, candidates == 1u << c);
    else moved = run_burst(c);  // mode 0, and reserved mode 3 treated alike
    budget -= std::min(moved, budget);
  }
  Cycles next = Scheduler::kNever;
  // A slice that used its whole budget continues one cycle later, so the scheduler's dispatch
  // loop returns and other events (frame end, run limits) still get their turn.
  if (budget == 0 && pick_channel(candidates) >= 0) next = sched_.now() + 1;
  for (u32 c = 0; c < kChannels; ++c) {
    const Channel& chan = channels_[c];
    if (!(chan.chcr & kChcrBusy) || !enabled(c)) continue;
    if (sched_.now() < chan.resume_at) next = std::min(next, chan.resume_at);
    else if (!may_run(c)) next = std::min(next, sched_.now() + kRequestPollCycles);
  }
  late_credit_ = 0;
  if (next == Scheduler::kNever) sched_.cancel(event_);
  else sched_.schedule_at(event_, next);
}

u32 Dma::run_burst(u32 ch) {
  Channel& c = channels_[ch];
  c.chcr &= ~kChcrTrigger;
  bool backward = c.chcr & kChcrBackward;
  u32 remaining = count_or_max(c.bcr & 0xFFFF);
  if (!(c.chcr & kChcrChopping)) {
    // Sync mode 0 leaves MADR and BCR at their start values (psx-spx).
    if (c.chcr & kChcrFromRam) to_device(ch, c.madr, remaining, backward);
    else from_device(ch, c.madr, remaining, backward);
    charge(ch, remaining);
    finish(ch);
    return remaining;
  }
  // Chopping: a window of 1<<N words, then the CPU runs for 1<<M clocks; MADR and BC advance.
  c.chopping_started = true;
  u32 n = std::min(remaining, 1u << ((c.chcr >> 16) & 7));
  if (c.chcr & kChcrFromRam) to_device(ch, c.madr, n, backward);
  else from_device(ch, c.madr, n, backward);
  c.madr = (backward ? c.madr - 4 * n : c.madr + 4 * n) & kAddressMask;
  c.bcr = (c.bcr & 0xFFFF0000) | ((remaining - n) & 0xFFFF);
  charge(ch, n);
  c.resume_at = sched_.now() - late_credit_ + (Cycles{1} << ((c.chcr >> 20) & 7)) + kChopGapCycles;
  if (remaining == n) finish(ch);
  return n;
}

u32 Dma::run_block(u32 ch) {
  Channel& c = channels_[ch];
  c.chcr &= ~kChcrTrigger;
  bool backward = c.chcr & kChcrBackward;
  u32 size = count_or_max(c.bcr & 0xFFFF);
  u32 blocks = count_or_max(c.bcr >> 16);
  if (c.chcr & kChcrFromRam) to_device(ch, c.madr, size, backward);
  else from_device(ch, c.madr, size, backward);
  // Sync mode 1 advances MADR and counts BA down to zero (psx-spx).
  c.madr = (backward ? c.madr - 4 * size : c.madr + 4 * size) & kAddressMask;
  c.bcr = (c.bcr & 0xFFFF) | (((blocks - 1) & 0xFFFF) << 16);
  charge(ch, size, kBlockExtraPer256Words);
  // The CPU gets the bus until the next block: the controller's gap, or longer while the device
  // still works through this block (the SPU's FIFO, spu/spu_transfer.cpp).
  const Cycles device = ch < Pio && ports_[ch] ? ports_[ch]->dma_block_cycles(size) : 0;
  if (blocks == 1) {
    finish(ch);
  } else if (device == 0 && device_request(ch)) {
    // A device that asks for the next block at once does not let the CPU onto the bus in the
    // gap: on a console a GPUSTAT read right after starting eight 1-word blocks to the GPU finds
    // all eight delivered (ps1-tests gpu/gpustat, sync mode cases). The gap is the controller's
    // own time, less what the CPU ran past the booking.
    const Cycles overlap = std::min(kBlockGapCycles, late_credit_);
    late_credit_ -= overlap;
    sched_.advance(kBlockGapCycles - overlap);
    c.resume_at = sched_.now();
  } else {
    c.resume_at = sched_.now() - late_credit_ + std::max(kBlockGapCycles, device);
  }
  return size;
}

// Sync mode 2: the controller reads a node's header, sends its words, then hands the bus back to
// the CPU before the next node (psx-spx "CPU Operation during DMA"). The nodes of a batch are
// walked in one call and their CPU gaps given together after it, so an ordering table of empty
// nodes costs one scheduler event per kListBatchNodes nodes; the CPU gets the same share of the
// time. may_run() can change only where words reach the device (its request follows the
// device's state, which nothing else changes during the batch) or where the list ends (finish()
// clears Busy), so after an empty node the answer last given still holds. Host time: the held
// cycles are added up and charged only where the device sees the time (before a node's words)
// and at the batch's end; charges add up exactly (charge_cycles256()), so the time each device
// write sees and the time the batch ends are those of charging every header and block at once.
u32 Dma::run_list(u32 ch, u32 budget, bool alone) {
  Channel& c = channels_[ch];
  c.chcr &= ~kChcrTrigger;
  const u32 max_nodes = alone ? kListBatchNodes : 1;
  const u64 word256 = clocks_per256_words(ch);
  u32 madr = c.madr;
  u32 moved = 0;
  u32 nodes = 0;
  u64 held256 = 0;       // held, not yet charged
  bool vouched = false;  // may_run() held after the trigger's clearing, and no words moved since
  for (;;) {
    // Node: header word (bits 24-31 word count, bits 0-23 next node), then the words for the
    // device.
    const u32 addr = madr & kAddressMask;
    const u32 header = bus_.dma_read_word(addr);
    const u32 count = header >> 24;
    madr = header & 0x00FFFFFF;
    moved += count + 1;
    ++nodes;
    held256 += kListHeader256;
    if (count) {
      charge_cycles256(held256 + kListPayloadSetup256);
      to_device(ch, addr + 4, count, false);
      held256 = u64{count} * word256;
      vouched = false;
    }
    // The hardware tests bit 23 alone for the list's end.
    if ((madr & 0x00800000) || nodes == max_nodes || moved >= budget) break;
    // As may_run(): Busy, the enable and resume_at stay as they were through the batch, and the
    // trigger was cleared above.
    if (!vouched && !(vouched = c.chopping_started || device_request(ch))) break;
  }
  charge_cycles256(held256);
  c.madr = madr;
  if (madr & 0x00800000) {
    // An end marker other than 0x00FFFFFF still ends the list, with the bus error flag raised: on
    // hardware 0x800000, 0x800001 and 0xFFFFF0 all leave DICR bit 15 set and MADR on the marker.
    if (madr != kListEnd) dicr_ |= kDicrBusError;
    finish(ch);
  } else {
    c.resume_at = sched_.now() - late_credit_ + Cycles{nodes} * kListGapCycles;
  }
  return moved;
}

u32 Dma::run_otc(u32 ch) {
  Channel& c = channels_[ch];
  c.chcr &= ~kChcrTrigger;
  // Reverse clear: each entry points at the one 4 bytes below it; the lowest ends the list.
  u32 n = count_or_max(c.bcr & 0xFFFF);
  u32 top = c.madr & kAddressMask;
  words_.resize(n);
  // words_[0] is the lowest address, top - 4*(n-1); entry i points 4 bytes below its own address.
  words_[0] = kListEnd;
  for (u32 i = 1, below = top - 4 * (n - 1); i < n; ++i, below += 4) words_[i] = below & 0x00FFFFFF;
  bus_.dma_write_ram(top - 4 * (n - 1), words_.data(), n);
  charge(ch, n);
  finish(ch);
  return n;
}

void Dma::finish(u32 ch) {
  Channel& c = channels_[ch];
  c.chcr &= ~(kChcrBusy | kChcrTrigger);
  c.chopping_started = false;
  // A channel's flag is set only while its interrupt is enabled in bits 16-22 (psx-spx).
  if ((dicr_ >> (16 + ch)) & 1) dicr_ |= 1u << (24 + ch);
  update_master_flag();
}

void Dma::to_device(u32 ch, u32 addr, u32 count, bool backward) {
  // Forward, the device reads the words where they lie in RAM: no device writes RAM while it
  // takes a block.
  if (const u32* in_place = backward ? nullptr : bus_.dma_ram_words(addr, count)) {
    if (ch < Pio && ports_[ch]) ports_[ch]->dma_write(in_place, count);
    return;
  }
  words_.resize(count);
  if (!backward) {
    bus_.dma_read_ram(addr, words_.data(), count);
  } else {
    bus_.dma_read_ram(addr - 4 * (count - 1), words_.data(), count);
    std::reverse(words_.begin(), words_.end());
  }
  if (ch < Pio && ports_[ch]) ports_[ch]->dma_write(words_.data(), count);
}

void Dma::from_device(u32 ch, u32 addr, u32 count, bool backward) {
  words_.resize(count);
  // With no device on the channel the bus floats high.
  if (ch < Pio && ports_[ch]) ports_[ch]->dma_read(words_.data(), count);
  else std::fill(words_.begin(), words_.end(), 0xFFFFFFFF);
  if (!backward) {
    bus_.dma_write_ram(addr, words_.data(), count);
  } else {
    std::reverse(words_.begin(), words_.end());
    bus_.dma_write_ram(addr - 4 * (count - 1), words_.data(), count);
  }
}

void Dma::charge(u32 ch, u32 words, u32 extra_per256) {
  charge_cycles256(u64{words} * (extra_per256 + clocks_per256_words(ch)));
}

u64 Dma::clocks_per256_words(u32 ch) const {
  // psx-spx lists CD-ROM DMA at 24 clocks a word with the BIOS's CDROM Delay/Size setting and 40
  // with the games' one: the rate follows the register (Bus::dma_word_cycles).
  return ch == Cdrom ? 256 * u64{bus_.dma_word_cycles(Bus::kCdromDelay)} : kClocksPer256Words[ch];
}

void Dma::charge_cycles256(u64 cycles256) {
  u64 total = charge_frac_ + cycles256;
  const Cycles held = total / 256;
  const Cycles overlap = std::min(held, late_credit_);
  late_credit_ -= overlap;
  sched_.advance(held - overlap);
  charge_frac_ = static_cast<u32>(total % 256);
}

void Dma::do_state(StateIO& s) {
  s.section("DMA ", 1);
  for (Channel& c : channels_) {
    s.pod(c.madr);
    s.pod(c.bcr);
    s.pod(c.chcr);
    s.boolean(c.chopping_started);
    s.pod(c.resume_at);
  }
  s.pod(dpcr_);
  s.pod(dicr_);
  s.pod(charge_frac_);
  s.end_section("DMA ");
}

}  // namespace psx
