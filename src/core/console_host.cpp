// Console services for the host: memory access without emulated side effects, RAM dumps,
// memory watches and save states.
#include <cstdio>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/console.h"
#include "core/endian.h"
#include "core/input_error.h"
#include "core/save_state.h"
#include "spu/wav.h"

namespace psx {

u8* Console::host_pointer(u32 addr, u32 width) const {
  u32 p = Bus::physical(addr);
  Bus& bus = const_cast<Bus&>(bus_);
  if ((addr & (width - 1)) == 0) {
    if (p < 0x00800000) return bus.ram() + (p & (Bus::kRamSize - 1));
    if (p >= MemoryWatches::kScratchBase && p < MemoryWatches::kScratchBase + Bus::kScratchSize)
      return bus.scratchpad() + (p - MemoryWatches::kScratchBase);
  }
  char msg[96];
  std::snprintf(msg, sizeof msg, "host memory access at 0x%08X: not an aligned RAM or scratchpad address", addr);
  throw std::invalid_argument(msg);
}

u16 Console::read16(u32 addr) const {
  return load_le16(host_pointer(addr, 2));
}
u32 Console::read32(u32 addr) const { return load_le32(host_pointer(addr, 4)); }
void Console::write16(u32 addr, u16 v) {
  ThreadOwner::Use use(owner_);
  store_le16(host_pointer(addr, 2), v);
  host_wrote(addr, 2);
}
void Console::write32(u32 addr, u32 v) {
  ThreadOwner::Use use(owner_);
  store_le32(host_pointer(addr, 4), v);
  host_wrote(addr, 4);
}

// A host write to RAM reaches the recompiler's code pages as a CPU store would, and one to RAM
// or the scratchpad the written pages (written_pages.h).
void Console::host_wrote(u32 addr, u32 width) {
  const u32 p = Bus::physical(addr);
  if (p < 0x00800000) bus_.host_wrote_ram(p & (Bus::kRamSize - 1), width);
  else bus_.host_wrote_scratchpad(p - MemoryWatches::kScratchBase, width);
}

void Console::dump_ram(const std::string& path) const {
  const u8* r = bus_.ram();
  write_file_atomically(path, std::vector<u8>(r, r + Bus::kRamSize));
}

void Console::save_screenshot(const std::string& path) const {
  std::string error;
  if (!gpu_.write_display_png(path, error)) throw InputError(error);
}

void Console::save_vram_png(const std::string& path) {
  std::string error;
  if (!gpu_.write_vram_png(path, error)) throw InputError(error);
}

void Console::save_wav(const std::string& path, const std::vector<StereoSample>& samples) {
  try {
    spu::write_wav(path, samples.data(), samples.size());
  } catch (const spu::WavError& e) {
    throw InputError(e.what());
  }
}

void Console::watch(const std::string& key, u32 addr, u32 length, bool fresh_only, u32 flow_limit_frames) {
  watches_.watch(key, addr, length, fresh_only, flow_limit_frames);
  bus_.attach_watches(&watches_, &frames_);
}

void Console::unwatch(const std::string& key) {
  watches_.unwatch(key);
  if (watches_.empty()) bus_.attach_watches(nullptr, nullptr);
}

std::vector<u8> Console::save_state(bool compress) {
  ThreadOwner::Use use(owner_);
  StateIO w;
  do_state(w);
  w.finish();
  SaveStateHeader h;
  h.compressed = compress;
  h.bios_hash = bios_hash_;
  h.program_hash = program_hash_;
  return pack_save_state(h, w.buffer());
}

void Console::load_state(const std::vector<u8>& blob) {
  ThreadOwner::Use use(owner_);
  u32 format = 0;
  std::vector<u8> payload = unpack_save_state(blob.data(), blob.size(), bios_hash_, program_hash_, &format);
  // A payload can still fail part-way (a block's section or range check): keep the current
  // state to put back, so a failed load leaves the console exactly as it was.
  StateIO backup;
  do_state(backup);
  try {
    StateIO r(payload.data(), payload.size(), format);
    do_state(r);
    r.finish();
  } catch (...) {
    StateIO restore(backup.buffer().data(), backup.buffer().size());
    do_state(restore);
    throw;
  }
  drop_stale_audio();
}

// Samples produced before a load belong to the abandoned timeline.
void Console::drop_stale_audio() {
  std::vector<StereoSample> stale;
  spu_.take_samples(stale);
  spu_.take_loud();
}

void Console::snapshot(Snapshot& out) {
  ThreadOwner::Use use(owner_);
  StateIO w;
  do_state(w);
  w.finish();
  out.payload_ = w.buffer();
  out.bios_hash_ = bios_hash_;
  out.program_hash_ = program_hash_;
  out.vram_token_ = gpu_.vram_token();
  out.ram_token_ = bus_.ram_token();
}

// The payload was written by do_state of a console with this BIOS and program, so it reads back
// completely (the section checks still guard against a snapshot that is not one).
void Console::restore(const Snapshot& snap) {
  ThreadOwner::Use use(owner_);
  if (snap.empty()) throw StateError("snapshot: empty (nothing was taken into it)");
  if (snap.bios_hash_ != bios_hash_ || snap.program_hash_ != program_hash_)
    throw StateError("snapshot: taken with a different BIOS, disc or EXE than the one loaded");
  StateIO r(snap.payload_.data(), snap.payload_.size());
  gpu_.expect_vram(snap.vram_token_);
  bus_.expect_ram(snap.ram_token_);
  try {
    do_state(r);
    r.finish();
  } catch (...) {
    gpu_.expect_vram(nullptr);  // no later load may take them for its own
    bus_.expect_ram(nullptr);
    throw;
  }
  drop_stale_audio();
}

void Console::save_state_file(const std::string& path, bool compress) {
  write_file_atomically(path, save_state(compress));
}

void Console::load_state_file(const std::string& path) {
  std::vector<u8> blob = read_file(path);
  try {
    load_state(blob);
  } catch (const StateError& e) {
    throw StateError(path + ": " + e.what());
  }
}

}  // namespace psx
