// Console: wiring of the hardware blocks, boot paths and the synchronous run loop.
#include "core/console.h"

#include <cstring>

#include "core/disc/disc_boot.h"
#include "core/hash.h"
#include "core/input_error.h"

namespace psx {

Console::Console()
    : bus_(sched_, irq_),
      cpu_(bus_, sched_, irq_, gte_),
      hle_(cpu_, bus_, sched_),
      cdrom_(sched_, irq_),
      sio0_(sched_, irq_),
      gpu_(sched_, irq_),
      spu_(sched_, irq_, cdrom_.audio_out()) {
  // The I/O region, in address order (psx-spx "Memory Map").
  bus_.map_io(Sio0::kBase, Sio0::kSize, &sio0_);
  bus_.map_io(Sio1::kBase, Sio1::kSize, &sio1_);
  bus_.map_io(Dma::kBase, Dma::kSize, &dma_);
  bus_.map_io(Timers::kBase, Timers::kSize, &timers_);
  bus_.map_io(Cdrom::kBase, Cdrom::kMapSize, &cdrom_);
  bus_.map_io(Gpu::kBase, Gpu::kSize, &gpu_);
  bus_.map_io(Mdec::kBase, Mdec::kSize, &mdec_);
  bus_.map_io(Spu::kBase, Spu::kSize, &spu_);

  dma_.connect(Dma::MdecIn, &mdec_.dma_in());
  dma_.connect(Dma::MdecOut, &mdec_.dma_out());
  dma_.connect(Dma::Gpu, &gpu_);
  dma_.connect(Dma::Cdrom, &cdrom_);
  dma_.connect(Dma::Spu, &spu_);
  // The root counters count the GPU's dots and HBlanks and synchronise to its blanking.
  gpu_.set_video_signals(&timers_);
  timers_.set_video_clock(&gpu_.video_clock());
  // A digital pad in controller port 1 (programs and BIOSes expect one).
  sio0_.attach_pad(0, std::make_unique<DigitalPad>());

  // A frame ends at the GPU's VBlank.
  gpu_.on_vblank = [this] {
    frame_done_ = true;
    ++frames_;
    watches_.on_frame(frames_, sched_.now());
    release_timed_buttons();
    cpu_.stop();
  };
  limit_event_ = sched_.add_event("run-limit", [this](Cycles) {
    limit_reached_ = true;
    cpu_.stop();
  });

  bus_.on_tty = [this](char c) {
    if (on_tty) on_tty(c);
  };
  bus_.on_exit_request = [this](u32 code) {
    exit_code_ = code;
    cpu_.stop();
  };
  bus_.on_log = [this](const std::string& m) { log(m); };
  bus_.on_fatal = [this](const std::string& m) {
    fatal_error_ = m;
    cpu_.stop();
  };
  cdrom_.on_log = bus_.on_log;
  hle_.on_tty = bus_.on_tty;
  hle_.on_log = bus_.on_log;
  hle_.on_fatal = [this](const std::string& m) { fatal_error_ = m; };
  hle_.pad_at = [this](int port) -> SioDevice* { return sio0_.pad(port); };
  hle_.disc_in_drive = [this] { return cdrom_.disc(); };
  hle_.card_at = [this](int slot) { return sio0_.memory_card(slot); };
  hle_.on_exit = bus_.on_exit_request;
  cpu_.reset();
  idle_skip_.set_spu(&spu_);
  set_idle_skip(true);
}

Console::~Console() = default;

void Console::set_cpu_mode(CpuMode mode) {
  ThreadOwner::Use use(owner_);
  const bool recompile = mode == CpuMode::Recompiler;
  // The code pages saw no RAM write while the interpreter ran, and native code trusts a cached
  // line whose tag matches unless a write marked it stale (ICache::kStale).
  if (recompile && cpu_mode() != CpuMode::Recompiler) recompiler_.drop_all();
  cpu_.set_recompiler(recompile ? &recompiler_ : nullptr);
  bus_.attach_code_pages(recompile ? &recompiler_.code_pages() : nullptr);
}

void Console::load_bios(const std::string& path) { load_bios_image(read_file(path), path); }

void Console::load_bios_image(const std::vector<u8>& image, const std::string& name) {
  ThreadOwner::Use use(owner_);
  if (image.size() != Bus::kBiosSize)
    throw InputError::whole(name, "a BIOS image must be exactly 524288 bytes (512 KiB), this file has " +
                                      std::to_string(image.size()));
  bus_.load_bios(image);
  recompiler_.drop_all();  // blocks compiled from the ROM before: no write reports a new image
  bios_hash_ = fnv1a(image.data(), image.size());
  cpu_.reset();
}

void Console::boot_bios() {
  ThreadOwner::Use use(owner_);
  hle_mode_ = false;
  // An EXE from an earlier boot_exe() must not be side-loaded into this boot (e.g. a disc's).
  pending_exe_.reset();
  cpu_.reset();
  cpu_.set_hooks(this, kShellEntry);
}

void Console::boot_exe(const std::string& path) { boot_exe_image(read_file(path), path); }

void Console::boot_exe_image(const std::vector<u8>& file, const std::string& name) {
  ThreadOwner::Use use(owner_);
  PsxExe exe = PsxExe::parse(file, name);
  program_hash_ = fnv1a(file.data(), file.size());
  if (bus_.has_bios()) {
    boot_bios();
    pending_exe_ = std::move(exe);
    return;
  }
  hle_mode_ = true;
  hle_.install();
  cpu_.set_hooks(this, 0x80000080);
  side_load(exe);
}

namespace {
// A disc's identity for save-state headers without reading the whole image: its table of
// contents and the system area's volume descriptors and first directory sectors (16-31), which
// hold the volume name and creation date.
u64 disc_identity(disc::Disc& d) {
  u64 h = kFnvOffset;
  for (const disc::Track& t : d.tracks()) {
    u32 toc[3] = {t.index1, t.end, static_cast<u32>(t.type)};
    h = fnv1a(toc, sizeof toc, h);
  }
  disc::RawSector sector;
  for (u32 lba = 16; lba < 32; ++lba)
    if (d.read_sector(lba + disc::kLeadInSectors, sector)) h = fnv1a(sector.data(), sector.size(), h);
  return h;
}
}  // namespace

void Console::insert_disc(const std::string& path) {
  ThreadOwner::Use use(owner_);
  cdrom_.insert_disc(disc::Disc::open(path));
  program_hash_ = disc_identity(*cdrom_.disc());
}

void Console::boot_disc() {
  ThreadOwner::Use use(owner_);
  if (!cdrom_.disc()) throw InputError("no disc inserted to boot from");
  if (bus_.has_bios()) {
    boot_bios();
    return;
  }
  disc::BootConfig config;
  PsxExe exe = disc::load_boot_exe(*cdrom_.disc(), config);
  hle_mode_ = true;
  hle_.install();
  cpu_.set_hooks(this, 0x80000080);
  side_load(exe);
}

void Console::side_load(const PsxExe& exe) {
  // What the BIOS's LoadExec() does: copy the text, clear the BSS, flush the i-cache (the BIOS
  // calls FlushCache after loading, so no line of older code survives), set PC/GP/SP/FP.
  for (u32 i = 0; i < exe.text.size(); ++i)
    bus_.ram()[(Bus::physical(exe.text_addr) + i) & (Bus::kRamSize - 1)] = exe.text[i];
  for (u32 i = 0; i < exe.bss_size; ++i) bus_.ram()[(Bus::physical(exe.bss_addr) + i) & (Bus::kRamSize - 1)] = 0;
  bus_.host_wrote_ram(Bus::physical(exe.text_addr) & (Bus::kRamSize - 1), u32(exe.text.size()));
  bus_.host_wrote_ram(Bus::physical(exe.bss_addr) & (Bus::kRamSize - 1), exe.bss_size);
  bus_.flush_icache();
  u32 sp = exe.stack_base ? exe.stack_base + exe.stack_offset : PsxExe::kDefaultStack;
  cpu_.set_reg(28, exe.gp);
  cpu_.set_reg(29, sp);
  cpu_.set_reg(30, sp);
  // The HLE kernel's Exec() caller: a return from the entry point stops with a message.
  if (hle_mode_) cpu_.set_reg(31, HleBios::kExitStub);
  cpu_.set_pc(exe.pc);
  if (hle_mode_) {
    // A BIOS hands over inside the critical section of its boot (HleBios::install), so the VBlank
    // of the frame before the program's is still pending in I_STAT (OpenBIOS leaves bit 0 set).
    irq_.raise(Irq::VBlank);
    hle_.start_program(exe.pc);
  }
}

void Console::on_reach(u32 pc) {
  u32 p = Bus::physical(pc);
  if (hle_mode_) {
    hle_.handle(pc);
    return;
  }
  // A real BIOS runs; print its putchar calls and let it continue.
  if (p == 0xA0 && (cpu_.reg(9) & 0xFF) == 0x3C && on_tty) on_tty(static_cast<char>(cpu_.reg(4)));
  if (p == 0xB0 && (cpu_.reg(9) & 0xFF) == 0x3D && on_tty) on_tty(static_cast<char>(cpu_.reg(4)));
  if (pc == kShellEntry && pending_exe_) {
    PsxExe exe = std::move(*pending_exe_);
    pending_exe_.reset();
    side_load(exe);
  }
}

void Console::run_frame() {
  ThreadOwner::Use use(owner_);
  frame_done_ = false;
  while (!frame_done_ && !stopped()) {
    cpu_.run();
    sched_.run_due_events();
  }
}

void Console::run_frames(u64 n) {
  ThreadOwner::Use use(owner_);
  for (u64 i = 0; i < n && !stopped(); ++i) run_frame();
}

void Console::run_cycles(Cycles n) {
  ThreadOwner::Use use(owner_);
  limit_reached_ = false;
  sched_.schedule(limit_event_, n);
  while (!limit_reached_ && !stopped()) {
    cpu_.run();
    sched_.run_due_events();
  }
  sched_.cancel(limit_event_);
}

bool Console::run_until(const std::function<bool()>& done, u64 max_frames) {
  ThreadOwner::Use use(owner_);
  for (u64 i = 0; i < max_frames && !stopped(); ++i) {
    if (done()) return true;
    run_frame();
  }
  return done();
}

void Console::do_state(StateIO& s) {
  // The SPU makes its samples lazily: those due belong to a saved state, and its event is booked
  // at its next sample so that the state does not depend on batching. A load replaces them: a
  // catch-up then would run to whatever clock a failed load left behind (a corrupt SCHD time can
  // be billions of samples ahead) before the backup is put back.
  if (!s.loading()) spu_.sync_for_state();
  s.section("CONS", 1);
  s.pod(frames_);
  s.boolean(hle_mode_);
  bool has_pending = pending_exe_.has_value();
  s.boolean(has_pending);
  if (has_pending) {
    if (s.loading()) pending_exe_.emplace();
    PsxExe& e = *pending_exe_;
    s.pod(e.pc), s.pod(e.gp), s.pod(e.text_addr), s.pod(e.text_size), s.pod(e.bss_addr), s.pod(e.bss_size);
    s.pod(e.stack_base), s.pod(e.stack_offset);
    s.vec(e.text, Bus::kRamSize);
  } else if (s.loading()) {
    pending_exe_.reset();
  }
  sched_.do_state(s);
  irq_.do_state(s);
  bus_.do_state(s);
  cpu_.do_state(s);
  gte_.do_state(s);
  hle_.do_state(s);
  cdrom_.do_state(s);
  sio0_.do_state(s);
  sio1_.do_state(s);
  dma_.do_state(s);
  timers_.do_state(s);
  mdec_.do_state(s);
  s.pod(hold_frames_);
  gpu_.do_state(s);
  spu_.do_state(s);
  if (s.loading()) cpu_.set_hooks(this, hle_mode_ ? 0x80000080 : kShellEntry);
  s.end_section("CONS");
}

}  // namespace psx
