// Bus: region decoding, access timing, I/O dispatch and the expansion-2 debug ports.
#include "core/bus.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <utility>

#include "core/irq.h"
#include "core/memory_control.h"

namespace psx {

namespace {
constexpr u32 kExp1Base = 0x1F000000, kExp1End = 0x1F800000;
constexpr u32 kScratchBase = 0x1F800000;
constexpr u32 kExp2Base = 0x1F802000;
constexpr u32 kExp3Base = 0x1FA00000, kExp3End = 0x1FC00000;
constexpr u32 kBiosBase = 0x1FC00000;
constexpr u32 kCacheControl = 0xFFFE0130;
constexpr u32 kCdromBase = 0x1F801800, kCdromEnd = 0x1F801810;
// The SPU timings apply to the SPU's 0x1F801C00 block and the unknown one after it (psx-spx).
constexpr u32 kSpuBase = 0x1F801C00, kSpuEnd = 0x1F802000;
constexpr u32 kComDelay = 8;

u32 load_width(const u8* p, u32 width) {
  switch (width) {
    case 1: return p[0];
    case 2: return p[0] | p[1] << 8;
    default: return load_le32(p);
  }
}
void store_width(u8* p, u32 v, u32 width) {
  p[0] = u8(v);
  if (width >= 2) p[1] = u8(v >> 8);
  if (width == 4) {
    p[2] = u8(v >> 16);
    p[3] = u8(v >> 24);
  }
}
}  // namespace

Bus::Bus(Scheduler& sched, InterruptController& irq)
    : sched_(sched), irq_(irq), ram_(kRamSize + kScratchSize, this), bios_(kBiosSize, 0) {
  // Power-on values of memory control 1 as the BIOS leaves them (psx-spx "Memory Control").
  memctrl_ = {0x1F000000, 0x1F802000, 0x0013243F, 0x00003022, 0x0013243F,
              0x200931E1, 0x00020843, 0x00070777, 0x00031125};
  update_read_cycles();
  set_cache_control(cache_control_);
}

void Bus::update_read_cycles() {
  for (u32 r = kExp1Delay; r <= kExp2Delay; ++r)
    for (u32 w : {1u, 2u, 4u})
      read_cycles_[r - kExp1Delay][w >> 1] = memory_read_cycles(memctrl_[r], memctrl_[kComDelay], w) - 1;
}

Cycles Bus::dma_word_cycles(DelayRegion r) const {
  return psx::dma_word_cycles(memctrl_[r], memctrl_[kComDelay]);
}

Cycles Bus::io_read_cycles(u32 p, u32 width) const {
  if (p >= kExp2Base) return read_cycles(kExp2Delay, width);
  if (p >= kSpuBase && p < kSpuEnd) return read_cycles(kSpuDelay, width);
  if (p >= kCdromBase && p < kCdromEnd) return read_cycles(kCdromDelay, width);
  return kIoRead;
}

void Bus::map_io(u32 phys_base, u32 size, IoDevice* dev) {
  for (u32 a = phys_base; a < phys_base + size; a += 16) {
    io_[(a - kIoBase) / 16] = dev;
    io_base_[(a - kIoBase) / 16] = phys_base;
  }
}

void Bus::load_bios(const std::vector<u8>& image) {
  std::memcpy(bios_.data(), image.data(), kBiosSize);
  has_bios_ = true;
}

void Bus::report_unmapped(u32 vaddr, const char* what) {
  // A program sweeping unmapped space would otherwise grow the set (and the log) per address.
  if (unmapped_.size() >= kMaxUnmappedReported) {
    if (!unmapped_capped_ && on_log)
      on_log("further unmapped accesses not reported (" + std::to_string(kMaxUnmappedReported) +
             " addresses reported)");
    unmapped_capped_ = true;
    return;
  }
  if (!unmapped_.insert(vaddr).second || !on_log) return;
  char msg[96];
  std::snprintf(msg, sizeof msg, "unmapped %s at 0x%08X (reported once)", what, vaddr);
  on_log(msg);
}

const u8* Bus::code_memory(u32 p) const {
  if (p < 0x00800000) return &ram_[p & (kRamSize - 1)];
  if (p >= kBiosBase && p < kBiosBase + kBiosSize) return &bios_[p - kBiosBase];
  return nullptr;  // the scratchpad is data cache and cannot be executed; I/O ports: fetch_slow()
}

// KUSEG and KSEG0 code runs through the i-cache when BCC.IS1 enables it: a hit is free and runs
// the cached word, a miss reads the words it fills at the uncached fetch cost each. KSEG1 code is
// always read from memory (psx-spx "Memory Map", i-Cache).
// Code also runs from the I/O ports a device answers (memory control, RAM size, I_STAT/I_MASK
// and the mapped devices), each word an uncached 32-bit I/O read with its time: ps1-tests
// cpu/code-in-io (hardware log tests/data/ps1-tests/cpu-code-in-io.log) returns from a JR $RA;
// NOP stored into the SPU's voice registers, DMA channel 0's BCR/CHCR and DPCR/DICR. Elsewhere
// (the scratchpad, a port no device answers) the fetch is a bus error, as the same log shows.
bool Bus::fetch_slow(u32 vaddr, u32& word, Cycles busy_until) {
  const u32 p = physical(vaddr);
  const u8* mem = code_memory(p);
  if (!mem) {
    const bool port = p >= kIoBase && p < kExp2Base &&
                      (p < kIoBase + 0x24 || (p & ~3u) == 0x1F801060 || (p & ~7u) == 0x1F801070 ||
                       io_[(p - kIoBase) / 16] != nullptr);
    if (!port) {
      report_unmapped(vaddr, "instruction fetch");
      return false;
    }
    if (sched_.now() < busy_until) sched_.advance(busy_until - sched_.now());
    sched_.advance(io_read_cycles(p, 4));
    word = io_read(p, 4);
    return true;
  }
  // Each word read from the BIOS is a 32-bit read over the ROM's bus.
  const Cycles word_cycles = p < 0x00800000 ? kRamFetchUncached : read_cycles(kBiosDelay, 4);
  const bool cached = cached_code(vaddr);
  if ((!cached || !icache_.hit(vaddr, p)) && sched_.now() < busy_until) sched_.advance(busy_until - sched_.now());
  if (!cached) {
    word = load_le32(mem);
    sched_.advance(word_cycles);
    return true;
  }
  if (!icache_.hit(vaddr, p)) {
    sched_.advance(word_cycles * icache_miss(vaddr, p, mem));
  } else {
    hot_lines_[ICache::line(vaddr)] = icache_.line_valid(vaddr) ? vaddr & ~15u : kNoLine;
  }
  word = icache_.code(vaddr);
  return true;
}

void Bus::fill_line_ahead(u32 vaddr, Cycles busy_until) {
  const u32 p = physical(vaddr);
  if ((vaddr & 3) || !cached_code(vaddr) || icache_.hit(vaddr, p) || !code_memory(p)) return;
  u32 word;
  fetch_slow(vaddr, word, busy_until);
}

// peek_code() outside RAM (the BIOS ROM) or misaligned.
bool Bus::peek_code_elsewhere(u32 vaddr, u32 p, u32& word) const {
  const u8* mem = code_memory(p);
  if ((vaddr & 3) || !mem) return false;
  const bool cached = vaddr < 0xA0000000 && (cache_control_ & kBccIs1) && icache_.hit(vaddr, p);
  word = cached ? icache_.code(vaddr) : load_le32(mem);
  return true;
}

bool Bus::read(u32 vaddr, u32& v, u32 width, bool time_ram) {
  u32 p = physical(vaddr);
  if (p < 0x00800000) {
    v = load_width(&ram_[p & (kRamSize - 1)], width);
    if (time_ram) sched_.advance(kRamRead);
    if (dcache_mode_) dcache_fill(vaddr, load_le32(&ram_[p & (kRamSize - 4)]));
    return true;
  }
  if (p >= kScratchBase && p < kScratchBase + kScratchSize && vaddr < 0xA0000000) {
    v = scratchpad_access(vaddr) ? load_width(scratchpad() + (p - kScratchBase), width) : 0;
    return true;
  }
  if (p >= kIoBase && p < kIoEnd) {
    read_io(vaddr, v, width);
    return true;
  }
  if (p >= kBiosBase && p < kBiosBase + kBiosSize) {
    v = load_width(&bios_[p - kBiosBase], width);
    sched_.advance(read_cycles(kBiosDelay, width));
    if (dcache_mode_) dcache_fill(vaddr, load_le32(&bios_[(p - kBiosBase) & ~3u]));
    return true;
  }
  if ((p >= kExp1Base && p < kExp1End) || (p >= kExp3Base && p < kExp3End)) {
    sched_.advance(read_cycles(p < kExp1End ? kExp1Delay : kExp3Delay, width));
    v = width == 4 ? 0xFFFFFFFF : (1u << (width * 8)) - 1;  // open expansion bus reads all ones
    return true;
  }
  if (vaddr == kCacheControl) {
    v = cache_control_;
    return true;
  }
  report_unmapped(vaddr, "read");
  return false;
}

bool Bus::read_merged(u32 vaddr, u32& v, u32 first, u32 count) {
  const u32 p = physical(vaddr);
  DelayRegion r;
  if (p >= kBiosBase && p < kBiosBase + kBiosSize) r = kBiosDelay;
  else if (p >= kExp1Base && p < kExp1End) r = kExp1Delay;
  else if (p >= kExp3Base && p < kExp3End) r = kExp3Delay;
  else if (p >= kExp2Base && p < kIoEnd) r = kExp2Delay;
  else if (p >= kSpuBase && p < kSpuEnd) r = kSpuDelay;
  else if (p >= kCdromBase && p < kCdromEnd) r = kCdromDelay;
  else return read32(vaddr, v);
  const u32 units = memory_bus_units(memctrl_[r], first, count);
  sched_.advance(memory_read_unit_cycles(memctrl_[r], memctrl_[kComDelay], units) - 1);
  if (r == kExp1Delay || r == kExp3Delay) {
    v = 0xFFFFFFFF;  // the open expansion bus, as read()
    return true;
  }
  v = r == kBiosDelay ? load_le32(&bios_[p - kBiosBase]) : io_read(p, 4);
  if (dcache_mode_) dcache_fill(vaddr, v);  // as read() for a word
  return true;
}

bool Bus::peek_data(u32 vaddr, u32 width, u32& v) {
  const u32 p = physical(vaddr);
  if (p < 0x00800000) v = load_width(&ram_[p & (kRamSize - 1)], width);
  else if (p >= kScratchBase && p < kScratchBase + kScratchSize && vaddr < 0xA0000000 && !dcache_mode_)
    v = load_width(scratchpad() + (p - kScratchBase), width);
  else if (p >= kIoBase && p < kIoEnd) v = io_read(p, width);
  else if (p >= kBiosBase && p < kBiosBase + kBiosSize) v = load_width(&bios_[p - kBiosBase], width);
  else return false;
  return true;
}

void Bus::watched_store(u8* mem, u32 phys, u32 v, u32 width) {
  u32 old = load_width(mem, width);
  store_width(mem, v, width);
  u32 mask = width == 4 ? 0xFFFFFFFF : (1u << (width * 8)) - 1;
  watches_->on_write(phys, width, old, v & mask, *frame_, sched_.now());
}

bool Bus::write(u32 vaddr, u32 v, u32 width) {
  u32 p = physical(vaddr);
  if (p < 0x00800000) {
    u32 off = p & (kRamSize - 1);
    if (code_pages_) code_pages_->on_ram_write(off);
    written_.mark(off);
    if (watches_ && watches_->ram_block_watched(off)) watched_store(&ram_[off], off, v, width);
    else store_width(&ram_[off], v, width);
    return true;
  }
  if (p >= kScratchBase && p < kScratchBase + kScratchSize && vaddr < 0xA0000000) {
    if (!scratchpad_access(vaddr)) return true;
    written_.mark(kRamSize + (p - kScratchBase));
    if (watches_) watched_store(scratchpad() + (p - kScratchBase), p, v, width);
    else store_width(scratchpad() + (p - kScratchBase), v, width);
    return true;
  }
  if (p >= kIoBase && p < kIoEnd) {
    io_write(p, v, width);
    return true;
  }
  if ((p >= kBiosBase && p < kBiosBase + kBiosSize) || (p >= kExp1Base && p < kExp1End) ||
      (p >= kExp3Base && p < kExp3End))
    return true;  // ROM and empty expansion space ignore writes
  if (vaddr == kCacheControl) {
    set_cache_control(v);
    return true;
  }
  report_unmapped(vaddr, "write");
  return false;
}

void Bus::read_io(u32 vaddr, u32& v, u32 width) {
  const u32 p = physical(vaddr);
  sched_.advance(io_read_cycles(p, width));
  v = io_read(p, width);
  // An I/O word load fills its slot too; what a narrower one leaves in the rest of the word is
  // not documented, so only word loads are modelled.
  if (dcache_mode_ && width == 4) dcache_fill(vaddr, v);
}

bool Bus::write_io(u32 vaddr, u32 v, u32 width) {
  const u32 p = physical(vaddr);
  if (p < kIoBase || p >= kIoEnd) return false;
  io_write(p, v, width);
  return true;
}

void Bus::set_cache_control(u32 v) {
  cache_control_ = v;
  hot_lines_.fill(kNoLine);
  dcache_mode_ = (v & (kBccRam | kBccDs)) == kBccDs;
}

// In D-cache mode the scratchpad is unmapped and an access to its addresses deadlocks the bus
// until a power cycle (psx-spx "Memory Control", "D-cache" mode): the console stops.
bool Bus::scratchpad_access(u32 vaddr) {
  if (!dcache_mode_) return true;
  char msg[112];
  std::snprintf(msg, sizeof msg, "scratchpad access at 0x%08X in data-cache mode hangs the bus (psx-spx Memory Control)", vaddr);
  if (on_fatal) on_fatal(msg);
  return false;
}

u32 Bus::io_read(u32 p, u32 width) {
  catch_up();
  u32 shift = (p & 3) * 8;
  if (p < kIoBase + 0x24) return memctrl_[(p - kIoBase) / 4] >> shift;
  if ((p & ~3u) == 0x1F801060) return ram_size_ >> shift;
  if ((p & ~7u) == 0x1F801070) return irq_.read(p & 0xF) >> shift;
  if (p >= kExp2Base) {
    // DUART status register A: report the transmitter ready and empty so TTY loops proceed.
    if (p == 0x1F802021) return 0x0C;
    // No dev-kit board is fitted: the open bus reads all ones (ps1-tests cpu/io-access-bitwidth,
    // hardware log: 0x1F802000 reads 0xFFFFFFFF whatever was written).
    return width == 4 ? 0xFFFFFFFF : (1u << (width * 8)) - 1;
  }
  u32 slot = (p - kIoBase) / 16;
  if (IoDevice* dev = io_[slot]) return dev->io_read(p - io_base_[slot], width);
  report_unmapped(p, "I/O read");
  return 0;
}

// The width of the register a port at physical address p holds (psx-spx "I/O Map"): the SIO,
// timer and SPU registers are 16 bits, the CD-ROM's and expansion 2's 8 bits, the rest 32.
static u32 io_port_width(u32 p) {
  if (p >= kExp2Base || (p >= kCdromBase && p < kCdromEnd)) return 1;
  if ((p >= 0x1F801040 && p < 0x1F801060) || (p >= 0x1F801100 && p < 0x1F801130) || (p >= kSpuBase && p < kSpuEnd))
    return 2;
  return 4;
}

// A CPU store narrower than the register it reaches writes the whole register: the CPU drives its
// full source register onto the data bus, moved to the addressed byte lane, and the port latches
// all of its own bits (ps1-tests cpu/io-access-bitwidth, hardware log: SB and SH of 0x12345678 to
// D0_MADR read back 0x345678, to DPCR 0x12345678, to T0_TARGET 0x5678). `v` is that register.
void Bus::io_write(u32 p, u32 v, u32 width) {
  catch_up();
  const u32 port = io_port_width(p);
  if (width < port) {
    const u32 lanes = v << ((p & 3) * 8);
    v = port == 4 ? lanes : (lanes >> ((p & 2) * 8)) & 0xFFFF;
    p &= ~(port - 1);
    width = port;
  } else if (width < 4) {
    v &= (1u << (width * 8)) - 1;
  }
  if (p < kIoBase + 0x24) {
    memctrl_[(p - kIoBase) / 4] = v;
    update_read_cycles();
    return;
  }
  if ((p & ~3u) == 0x1F801060) {
    ram_size_ = v;
    return;
  }
  if ((p & ~7u) == 0x1F801070) {
    irq_.write(p & 0xF, v);
    return;
  }
  if (p >= kExp2Base) {
    expansion2_write(p, v, width);
    return;
  }
  u32 slot = (p - kIoBase) / 16;
  if (IoDevice* dev = io_[slot]) {
    dev->io_write(p - io_base_[slot], v, width);
    return;
  }
  report_unmapped(p, "I/O write");
}

void Bus::expansion2_write(u32 p, u32 v, u32 width) {
  switch (p) {
    case 0x1F802023:  // dev-kit DUART channel A transmit
    case 0x1F802080:  // emulator debug console
      if (on_tty) on_tty(static_cast<char>(v & 0xFF));
      return;
    case 0x1F802082:
      if (width == 2 && on_exit_request) on_exit_request(v & 0xFFFF);
      return;
    case 0x1F802041:  // POST 7-segment display: nothing to show
      return;
    default:
      return;  // other DUART and dev-kit registers: writes have no visible effect here
  }
}

void Bus::dma_write_ram(u32 addr, const u32* words, u32 count) {
  // In runs up to RAM's end, where the address wraps; the code pages hear of a run at once, and
  // a run no memory watch sees is one copy.
  for (u32 i = 0; i < count;) {
    const u32 start = (addr + i * 4) & (kRamSize - 4);
    const u32 run = std::min(count - i, (kRamSize - start) / 4);
    if (code_pages_) code_pages_->on_ram_range(start, run * 4);
    written_.mark_range(start, run * 4);
    if (!watches_) {
      store_le32_words(&ram_[start], words + i, run);
      i += run;
      continue;
    }
    for (u32 off = start; off < start + run * 4; off += 4, ++i) {
      if (watches_->ram_block_watched(off)) watched_store(&ram_[off], off, words[i], 4);
      else store_le32(&ram_[off], words[i]);
    }
  }
}

void Bus::dma_read_ram(u32 addr, u32* words, u32 count) const {
  for (u32 i = 0; i < count;) {  // in runs up to RAM's end, as dma_write_ram()
    const u32 start = (addr + i * 4) & (kRamSize - 4);
    const u32 run = std::min(count - i, (kRamSize - start) / 4);
    load_le32_words(words + i, &ram_[start], run);
    i += run;
  }
}

std::shared_ptr<const void> Bus::ram_token() {
  if (ram_lent_ || !ram_token_ || written_.any()) {
    ram_token_ = std::make_shared<const int>(0);  // stands for RAM's and the scratchpad's contents now
    written_.clear();
  }
  return ram_token_;
}

void Bus::do_state(StateIO& s) {
  s.section("BUS ", 2);
  std::vector<std::pair<u32, u32>> compiled;
  if (s.loading() && code_pages_) compiled = code_pages_->compiled_words(ram_.data());
  // RAM and the scratchpad lie one after the other here and in the state. A snapshot of them as
  // they still are but for the pages written since (ram_token()) needs only those copied back.
  // expect_ram() speaks for this load only, whichever way it goes.
  static_assert(WrittenPages::kBytes == kRamSize + kScratchSize);
  if (!s.loading()) {
    s.bytes(ram_.data(), WrittenPages::kBytes);
  } else {
    std::shared_ptr<const void> expected = std::exchange(expected_ram_, nullptr);
    if (expected && expected == ram_token_ && !ram_lent_) {
      written_.copy_back(ram_.data(), s.skip(WrittenPages::kBytes));
    } else {
      s.bytes(ram_.data(), WrittenPages::kBytes);
      written_.clear();
    }
    ram_token_ = std::move(expected);
  }
  s.pod(memctrl_);
  s.pod(ram_size_);
  s.pod(cache_control_);
  update_read_cycles();  // derived from memctrl_
  set_cache_control(cache_control_);
  if (icache_.do_state(s) < ICache::kWordsSince && s.loading())
    icache_.refill_valid([this](u32 p) { return code_memory(p); });
  if (s.loading()) {
    recheck_icache_lines();
    if (code_pages_) code_pages_->written_by_load(ram_.data(), compiled);
  }
  s.end_section("BUS ");
}

}  // namespace psx
