// The PlayStation memory map (psx-spx "Memory Map"): KUSEG/KSEG0/KSEG1 mirrors of the physical
// space, 2 MiB RAM mirrored through the first 8 MiB, the 1 KiB scratchpad (data cache used as
// RAM), the 512 KiB BIOS ROM, expansion regions 1-3, the I/O ports and the KSEG2 cache control
// register. Every CPU and DMA access to memory goes through here.
#pragma once
#include <array>
#include <bit>
#include <functional>
#include <set>
#include <memory>
#include <string>
#include <vector>

#include "core/cpu/icache.h"
#include "core/cpu/recompiler/code_pages.h"
#include "core/endian.h"
#include "core/io_device.h"
#include "core/memory_watch.h"
#include "core/near_memory.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"
#include "core/written_pages.h"

namespace psx {

class InterruptController;

class Bus {
 public:
  static constexpr u32 kRamSize = 2 * 1024 * 1024;
  static constexpr u32 kScratchSize = 1024;
  // The recompiler's pages cover this RAM and the scratchpad after it (scratchpad()).
  static_assert(kRamSize == CodePages::kRamSize && kScratchSize == CodePages::kScratchBytes);
  static constexpr u32 kBiosSize = 512 * 1024;

  Bus(Scheduler& sched, InterruptController& irq);

  // Physical address for a virtual one (psx-spx region masks). KSEG2 is not translated.
  static u32 physical(u32 vaddr) {
    static constexpr u32 kRegionMask[8] = {0xFFFFFFFF, 0xFFFFFFFF, 0xFFFFFFFF, 0xFFFFFFFF,
                                           0x7FFFFFFF, 0x1FFFFFFF, 0xFFFFFFFF, 0xFFFFFFFF};
    return vaddr & kRegionMask[vaddr >> 29];
  }

  // CPU accesses. They return false on a bus error (the CPU raises IBE/DBE) and charge the
  // region's access time to the scheduler.
  // `busy_until`: when a data load in flight ends its RAM access (cpu.h, load shadow); a fetch
  // that must read memory waits for it.
  bool fetch(u32 vaddr, u32& word, Cycles busy_until = 0) {
    if (hot_lines_[ICache::line(vaddr)] == (vaddr & ~15u)) {  // a cache hit: free
      word = icache_.code(vaddr);
      return true;
    }
    return fetch_slow(vaddr, word, busy_until);
  }
  // fetch()'s free path alone: the word when vaddr is an i-cache hit on a line held whole (no
  // time, no fill), else false (fetch() would take its slow path).
  bool fetch_hit(u32 vaddr, u32& word) const {
    if (hot_lines_[ICache::line(vaddr)] != (vaddr & ~15u)) return false;
    word = icache_.code(vaddr);
    return true;
  }
  // The word fetch() would execute at vaddr (the cached copy on a hit), without timing or fills;
  // false where fetch() would fail or read an I/O port (a read there may act). Inline for RAM,
  // where idle skipping looks at each word of a loop it repeats.
  bool peek_code(u32 vaddr, u32& word) const {
    const u32 p = physical(vaddr);
    if (p >= 0x00800000 || (vaddr & 3)) return peek_code_elsewhere(vaddr, p, word);
    word = cached_code(vaddr) && icache_.hit(vaddr, p) ? icache_.code(vaddr) : load_le32(&ram_[p & (kRamSize - 1)]);
    return true;
  }
  // Whether the memory at vaddr (RAM or the BIOS ROM, past the i-cache) holds `word`.
  bool memory_holds(u32 vaddr, u32 word) const {
    const u8* mem = code_memory(physical(vaddr));
    return mem && load_le32(mem) == word;
  }
  // A store while SR.IsC isolates the cache never reaches memory. With BCC.TAG and IS1 it writes
  // the addressed i-cache line's tag; without TAG it would write cache data, whose exact effect
  // is not documented and is not modelled.
  void isolated_store(u32 vaddr, u32 v) {
    if ((cache_control_ & (kBccTag | kBccIs1)) == (kBccTag | kBccIs1)) {
      icache_.write_tag(vaddr, physical(vaddr), v);
      hot_lines_[ICache::line(vaddr)] = kNoLine;
    }
  }
  // What the BIOS's FlushCache leaves: every i-cache line invalid.
  void flush_icache() {
    icache_.invalidate_all();
    hot_lines_.fill(kNoLine);
  }
  const ICache& icache() const { return icache_; }
  // fetch_hit()'s table in place (kLines entries: a line's address where it is held whole, else
  // no_hot_line()), for the recompiler's native i-cache fills, which keep it as icache_miss().
  u32* hot_lines_cell() { return hot_lines_.data(); }
  static constexpr u32 no_hot_line() { return kNoLine; }
  // The cache control register in place and its i-cache enable bit (cached_code()), for the
  // recompiler's native code, which checks i-cache hits word by word (ICache::tags()).
  const u32* cache_control_cell() const { return &cache_control_; }
  static constexpr u32 icache_enable_bit() { return kBccIs1; }
  // The i-cache block size bits (IBLKSZ): clear, a fill entered at a line's first word stops
  // after two words.
  static constexpr u32 icache_block_bits() { return kBccIblksz; }
  // BCC selects D-cache mode: loads from RAM also write the scratchpad (see dcache_fill()).
  bool dcache_mode() const { return dcache_mode_; }
  // dcache_mode() and the attached memory watches in place, for the recompiler's native loads
  // and stores, which leave D-cache mode and watched writes to read() and write().
  const bool* dcache_mode_cell() const { return &dcache_mode_; }
  MemoryWatches* const* watches_cell() const { return &watches_; }
  bool read32(u32 vaddr, u32& v) { return read(vaddr, v, 4); }
  bool read16(u32 vaddr, u32& v) { return read(vaddr, v, 2); }
  bool read8(u32 vaddr, u32& v) { return read(vaddr, v, 1); }
  // LWL/LWR's read of the word at vaddr (aligned) that merges only its bytes first..first+count-1:
  // on a region timed by a Delay/Size register (BIOS, expansion, SPU, CD-ROM) it takes only the
  // 8/16-bit bus units holding those bytes (Mednafen's cpu.cpp reads 8, 16 or 24 bits for them; ps1-tests
  // cpu/access-time: an unaligned SPU word read by LWL+LWR costs what an aligned one does, not
  // twice that). Elsewhere it is read32().
  bool read_merged(u32 vaddr, u32& v, u32 first, u32 count);
  // Whether a load from vaddr uses the CPU's bus interface: not RAM (timed by the CPU's load
  // shadow when cached code makes it), the scratchpad or the cache control register.
  static bool bus_load(u32 vaddr) {
    const u32 p = physical(vaddr);
    return p >= 0x1F000000 && p < 0x1FC80000 && (p >= 0x1F800400 || p < 0x1F800000);
  }
  // Whether the CPU's fetch at vaddr would go to memory (an i-cache miss or uncached code).
  bool fetch_misses(u32 vaddr) const { return !cached_code(vaddr) || !icache_.hit(vaddr, physical(vaddr)); }
  // The value a load of `width` bytes at vaddr would read now, without the load's time, from RAM,
  // the scratchpad (outside D-cache mode), the BIOS ROM or an I/O register; false elsewhere. An
  // I/O register is read through its device, so only for registers whose read has no side
  // effect (idle skipping's pure loads, idle_skip.cpp).
  bool peek_data(u32 vaddr, u32 width, u32& v);
  // Memory Control 1 (1F801000h-1F801020h): it times reads on the external bus and some I/O.
  const std::array<u32, 9>& memory_control() const { return memctrl_; }
  // A read whose RAM access time the caller charges itself (the CPU's load shadow, cpu.h);
  // other regions are charged as by read().
  bool read_ram_untimed(u32 vaddr, u32& v, u32 width) { return read(vaddr, v, width, false); }
  // Whether code at vaddr runs through the i-cache (KUSEG/KSEG0 with BCC.IS1).
  bool cached_code(u32 vaddr) const { return vaddr < 0xA0000000 && (cache_control_ & kBccIs1); }
  // For write16() and write8(), v may hold more than the stored bytes: memory takes the low ones,
  // an I/O register wider than the store takes all it holds (io_write()).
  bool write32(u32 vaddr, u32 v) { return write(vaddr, v, 4); }
  bool write16(u32 vaddr, u32 v) { return write(vaddr, v, 2); }
  bool write8(u32 vaddr, u32 v) { return write(vaddr, v, 1); }
  // A CPU store of `width` bytes (v is the CPU's whole source register: a narrow store to an I/O
  // register writes all of it, io_write()) as write() makes it when vaddr lies in the
  // I/O region (physical 1F801000h-1F802FFFh); false, with nothing written, anywhere else. For
  // the recompiler's store calls, whose native code makes the RAM and scratchpad stores itself.
  bool write_io(u32 vaddr, u32 v, u32 width);
  // An i-cache miss at vaddr filled now, as fetch() would fill it (waiting for `busy_until`
  // first); nothing where fetch() would hit, read uncached memory or fail. For the CPU's stores
  // to I/O: the refill of the next instruction's line takes the bus before the store, which waits
  // in the write queue.
  void fill_line_ahead(u32 vaddr, Cycles busy_until);
  // Whether vaddr lies in the I/O region, where read_io() and write_io() reach.
  static bool io_address(u32 vaddr) {
    const u32 p = physical(vaddr);
    return p >= kIoBase && p < kIoEnd;
  }
  // A CPU load of `width` bytes from the I/O region as read() makes it (the port's access time,
  // then its value); for the recompiler's load calls. The caller checks io_address() first.
  void read_io(u32 vaddr, u32& v, u32 width);

  // Maps a block's registers into the I/O region (physical 0x1F801000-0x1F802FFF, 16-byte units).
  void map_io(u32 phys_base, u32 size, IoDevice* dev);

  // DMA moves whole words between RAM and devices; addresses wrap inside the 2 MiB RAM.
  void dma_write_ram(u32 addr, const u32* words, u32 count);
  void dma_read_ram(u32 addr, u32* words, u32 count) const;
  // One word, as dma_read_ram() reads it (a linked list's node header, once per node).
  u32 dma_read_word(u32 addr) const { return load_le32(&ram_[addr & (kRamSize - 4)]); }
  // The `count` words dma_read_ram() would read from addr, in place: RAM itself where they do not
  // wrap past its end and the host is little-endian like the console, else null (copy them).
  // Valid until RAM is next written. Spares a GPU list node's copy before the GPU copies it again.
  const u32* dma_ram_words(u32 addr, u32 count) const {
    if constexpr (std::endian::native != std::endian::little) return nullptr;
    const u32 start = addr & (kRamSize - 4);
    if (u64{start} + u64{count} * 4 > kRamSize) return nullptr;
    return reinterpret_cast<const u32*>(&ram_[start]);
  }

  void load_bios(const std::vector<u8>& image);
  bool has_bios() const { return has_bios_; }

  u8* ram() { return ram_.data(); }
  const u8* ram() const { return ram_.data(); }
  // The scratchpad's 1 KiB lie right after RAM's 2 MiB (the recompiler's native loads and stores
  // reach both from one base: offset kRamSize + n is scratchpad byte n).
  u8* scratchpad() { return ram_.data() + kRamSize; }
  const u8* scratchpad() const { return ram_.data() + kRamSize; }
  u8* bios() { return bios_.data(); }

  // Debug ports in expansion region 2 (DESIGN.md "Debug ports").
  std::function<void(char)> on_tty;
  std::function<void(u32 code)> on_exit_request;
  // Where unmapped and not-yet-emulated accesses are reported (once per address, for the first
  // kMaxUnmappedReported addresses; then one line says further ones are not reported).
  std::function<void(const std::string&)> on_log;
  static constexpr size_t kMaxUnmappedReported = 64;
  size_t unmapped_reported() const { return unmapped_.size(); }
  // An access that hangs the real bus (the console cannot go on).
  std::function<void(const std::string&)> on_fatal;

  // Memory watches see every RAM/scratchpad write (CPU and DMA) while attached; `frame` is the
  // console's frame counter, stamped on each event. Detached (nullptr) the write path is unchanged.
  void attach_watches(MemoryWatches* w, const u64* frame) {
    watches_ = w;
    frame_ = frame;
  }

  // The recompiler's page map (code_pages.h) sees every CPU and DMA write to RAM while attached.
  void attach_code_pages(CodePages* pages) {
    code_pages_ = pages;
    if (pages) pages->watch(&icache_);
  }
  // A write to `bytes` bytes of RAM from offset `off` made outside the CPU and DMA (a host poke,
  // the HLE BIOS, an EXE loaded), reported to the code pages and the written pages as theirs are.
  // The range may wrap past RAM's end.
  void host_wrote_ram(u32 off, u32 bytes) {
    if (u64{off} + bytes > kRamSize) written_.mark_all();
    else written_.mark_range(off, bytes);
    if (!code_pages_ || bytes == 0) return;
    for (u32 w = off & ~3u; w != ((off + bytes + 3) & ~3u); w += 4) code_pages_->on_ram_write(w & (kRamSize - 4));
  }
  // A host write to `bytes` bytes of the scratchpad from byte `off`.
  void host_wrote_scratchpad(u32 off, u32 bytes) { written_.mark_range(kRamSize + off, bytes); }
  // A token for RAM and the scratchpad as they are now, which a snapshot keeps
  // (Console::Snapshot): they keep it while nothing writes them, and restoring a snapshot whose
  // token they still hold copies back only the pages written since (written_pages.h).
  std::shared_ptr<const void> ram_token();
  // The next do_state() load restores a snapshot taken with `token` (null: any other state).
  void expect_ram(std::shared_ptr<const void> token) { expected_ram_ = std::move(token); }
  // RAM or the scratchpad was lent out for writing in place (Console::ram()), where no write is
  // reported: from now on restores copy them whole.
  void lend_ram() { ram_lent_ = true; }
  // The written pages' bytes, which the recompiler's native stores set.
  u8* written_pages() { return written_.data(); }
  // After the recompiler has dropped the blocks whose code was written: each i-cache line stale
  // exactly where its words differ from memory (ICache::kStale).
  void recheck_icache_lines() {
    icache_.mark_stale_lines([this](u32 p) { return code_memory(p); });
  }

  void do_state(StateIO& s);

  // Read times in CPU cycles beyond the instruction's own cycle. RAM, scratchpad and the on-chip
  // I/O ports have fixed times (JaCzekanski's ps1-tests cpu/access-time, hardware log: a load
  // costs 5 cycles from RAM, 3 from DMA/IRQ/timer/pad/GPU/MDEC registers, 1 from the scratchpad).
  // The BIOS ROM, expansion regions, SPU and CD-ROM take the times their Memory Control
  // Delay/Size registers select (see read_cycles()). Stores go through the CPU's write queue and
  // take no extra time (psx-spx "CPU Load/Store Opcodes"; the queue filling up is not modelled).
  // Loads from RAM by cached code are timed by the CPU instead (read_ram_untimed, the load shadow
  // in cpu.h); kRamRead is the time of the others (loads made by uncached code).
  static constexpr Cycles kRamFetchUncached = 4;  // per word, also for each word of an i-cache fill
  static constexpr Cycles kRamRead = 4;
  static constexpr Cycles kIoRead = 2;

  // Memory Control 1 registers with a Delay/Size layout, indexed as memctrl_ is.
  enum DelayRegion : u32 { kExp1Delay = 2, kExp3Delay, kBiosDelay, kSpuDelay, kCdromDelay, kExp2Delay };
  // Extra cycles of a `width`-byte read from a Delay/Size region under the current settings.
  Cycles read_cycles(DelayRegion r, u32 width) const { return read_cycles_[r - kExp1Delay][width >> 1]; }
  // Cycles a DMA channel spends per word on a Delay/Size region's bus (memory_control.h).
  Cycles dma_word_cycles(DelayRegion r) const;

 private:
  bool fetch_slow(u32 vaddr, u32& word, Cycles busy_until);
  // Fills vaddr's line from `mem`, which holds vaddr's word, and keeps hot_lines_ in step;
  // returns the words read.
  u32 icache_miss(u32 vaddr, u32 p, const u8* mem) {
    const u32 n = icache_.fill(vaddr, p, (cache_control_ & kBccIblksz) == 0, mem - 4 * ICache::word(vaddr));
    hot_lines_[ICache::line(vaddr)] = icache_.line_valid(vaddr) ? vaddr & ~15u : kNoLine;
    return n;
  }
  // The memory holding the code word at physical address p (RAM or BIOS ROM), or nullptr.
  const u8* code_memory(u32 p) const;
  bool peek_code_elsewhere(u32 vaddr, u32 p, u32& word) const;
  void update_read_cycles();
  Cycles io_read_cycles(u32 p, u32 width) const;
  bool read(u32 vaddr, u32& v, u32 width, bool time_ram = true);
  bool write(u32 vaddr, u32 v, u32 width);
  u32 io_read(u32 p, u32 width);
  void io_write(u32 p, u32 v, u32 width);
  void expansion2_write(u32 p, u32 v, u32 width);
  void report_unmapped(u32 vaddr, const char* what);
  void watched_store(u8* mem, u32 phys, u32 v, u32 width);
  void set_cache_control(u32 v);
  bool scratchpad_access(u32 vaddr);
  // D-cache mode (psx-spx "Memory Control", BCC RAM=0 DS=1): every load from a cached segment
  // misses and copies the whole word holding the loaded byte into scratchpad slot (addr>>2)&FFh.
  void dcache_fill(u32 vaddr, u32 word) {
    if (vaddr >= 0xA0000000) return;
    store_le32(scratchpad() + (vaddr & 0x3FC), word);
    written_.mark(kRamSize + (vaddr & 0x3FC));
  }
  // Device events fall due between instructions; an I/O access in the middle of an instruction
  // (after its wait states) first runs the ones already due, so the device answers as of "now".
  void catch_up() {
    if (sched_.now() >= sched_.next_deadline()) sched_.run_due_events();
  }

  Scheduler& sched_;
  InterruptController& irq_;
  NearMemory ram_;  // RAM, then the scratchpad (scratchpad()), near the CPU for native code
  std::vector<u8> bios_;
  bool has_bios_ = false;

  // Memory control 1 (0x1F801000-0x1F801023), RAM_SIZE (0x1F801060) and cache control.
  std::array<u32, 9> memctrl_{};
  u32 ram_size_ = 0x00000B88;
  // BIU/cache configuration (psx-spx "Memory Control", FFFE0130h), reset to the value the BIOS
  // sets (scratchpad, 4-word i-cache refill, i-cache on), as memctrl_ is.
  static constexpr u32 kBccTag = 1u << 2, kBccRam = 1u << 3, kBccDs = 1u << 7;
  static constexpr u32 kBccIblksz = 3u << 8, kBccIs1 = 1u << 11;
  u32 cache_control_ = 0x0001E988;
  bool dcache_mode_ = false;  // derived from cache_control_
  ICache icache_;
  // Per i-cache line, the KUSEG/KSEG0 address of the line it holds whole, or kNoLine: fetches
  // from it are hits without a tag check (an interpreter speed-up derived from the tags, reset
  // whenever a tag or BCC changes).
  static constexpr u32 kNoLine = 1;
  std::array<u32, ICache::kLines> hot_lines_;
  // read_cycles() for each Delay/Size region and width 1, 2, 4 (index width >> 1), derived from
  // memctrl_ whenever it changes.
  std::array<std::array<Cycles, 3>, 6> read_cycles_{};

  static constexpr u32 kIoBase = 0x1F801000;
  static constexpr u32 kIoSlots = 0x2000 / 16;
  static constexpr u32 kIoEnd = kIoBase + kIoSlots * 16;
  std::array<IoDevice*, kIoSlots> io_{};
  std::array<u32, kIoSlots> io_base_{};
  std::set<u32> unmapped_;  // addresses already reported
  bool unmapped_capped_ = false;
  MemoryWatches* watches_ = nullptr;
  const u64* frame_ = nullptr;
  CodePages* code_pages_ = nullptr;
  // ram_token(): the token RAM and the scratchpad hold, with the pages written since they got it;
  // expect_ram()'s; lend_ram().
  WrittenPages written_;
  std::shared_ptr<const void> ram_token_, expected_ram_;
  bool ram_lent_ = false;
};

}  // namespace psx
