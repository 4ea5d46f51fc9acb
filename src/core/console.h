// The emulated PlayStation and the emulator's only public face: every hardware block lives here,
// wired together, on one scheduler timeline. Environments, Lua, Python and the CLI use nothing
// else from the core. A console is self-contained (no global state): many can run on many
// threads. It never starts threads itself; every run call returns synchronously. One thread at a
// time per console: booting, running, input or a save state from a second thread while one is
// inside throws std::runtime_error("Console is in use by another thread") (util/thread_owner.h).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/audio_fifo.h"
#include "core/bios/exe.h"
#include "core/bios/hle_bios.h"
#include "core/bus.h"
#include "core/cdrom/cdrom.h"
#include "core/cpu/cpu.h"
#include "core/cpu/idle_skip.h"
#include "core/cpu/recompiler/recompiler.h"
#include "core/dma.h"
#include "core/gte/gte.h"
#include "core/input_error.h"
#include "core/irq.h"
#include "core/mdec.h"
#include "core/memory_watch.h"
#include "core/scheduler.h"
#include "core/sio/sio0.h"
#include "core/sio/sio1.h"
#include "core/state.h"
#include "util/thread_owner.h"
#include "core/timers.h"
#include "gpu/gl/gl_context.h"
#include "gpu/gpu.h"
#include "spu/spu.h"

namespace psx {

class Console : private CpuHooks {
 public:
  // PS-X EXE shell entry: with a real BIOS, EXEs are side-loaded when the BIOS gets here.
  static constexpr u32 kShellEntry = 0x80030000;

  Console();
  ~Console() override;
  Console(const Console&) = delete;
  Console& operator=(const Console&) = delete;

  // A BIOS image must be exactly 512 KiB; throws InputError otherwise. Resets the console.
  void load_bios(const std::string& path);
  void load_bios_image(const std::vector<u8>& image, const std::string& name);
  bool has_bios() const { return bus_.has_bios(); }

  // Boots a PS-X EXE: with a BIOS, runs it from reset and side-loads at the shell entry; without,
  // the HLE kernel loads it at once. Throws InputError for a defective file.
  void boot_exe(const std::string& path);
  void boot_exe_image(const std::vector<u8>& file, const std::string& name);
  // With a BIOS, an EXE given to boot_exe() waits until the BIOS reaches its shell entry and is
  // then side-loaded: true while it still waits (the BIOS has not got that far).
  bool exe_pending() const { return pending_exe_.has_value(); }
  // Boots the BIOS alone (from reset), e.g. for a BIOS test or a disc.
  void boot_bios();

  // Disc drive: opens a .cue/.iso/.bin image (throws InputError naming file and line), and boots
  // the inserted disc: the BIOS reads SYSTEM.CNF itself, or without a BIOS the HLE fast boot
  // loads SYSTEM.CNF's BOOT executable through ISO 9660.
  void insert_disc(const std::string& path);
  void boot_disc();

  // Runs to the end of the current frame (the GPU's next VBlank) or until the program stops.
  void run_frame();
  void run_frames(u64 n);
  void run_cycles(Cycles n);
  // Runs whole frames until `done()` holds after a frame (checked before the first frame too) or
  // `max_frames` have run; returns whether `done()` held.
  bool run_until(const std::function<bool()>& done, u64 max_frames);

  // The program wrote its exit code to the debug port, or the console hit a fatal guest error.
  bool stopped() const { return exit_code_.has_value() || !fatal_error_.empty(); }
  std::optional<u32> exit_code() const { return exit_code_; }
  const std::string& fatal_error() const { return fatal_error_; }

  // Idle-loop skipping (core/cpu/idle_skip.h), on by default: loops that only wait for the next
  // event are accounted for without executing them. The results are bit-identical either way;
  // turning it off is for comparing that, and for measuring.
  void set_idle_skip(bool on) { cpu_.set_idle_skip(on ? &idle_skip_ : nullptr); }
  bool idle_skip() const { return cpu_.idle_skip_enabled(); }
  const IdleSkip::Stats& idle_skip_stats() const { return idle_skip_.stats(); }

  // Which CPU core runs programs: the interpreter (the default and the reference) or the
  // recompiler (core/cpu/recompiler/recompiler.h). Both compute the same states, cycle for cycle;
  // the mode is a host setting, not machine state (save states do not record it).
  enum class CpuMode { Interpreter, Recompiler };
  void set_cpu_mode(CpuMode mode);
  CpuMode cpu_mode() const { return cpu_.recompiler_enabled() ? CpuMode::Recompiler : CpuMode::Interpreter; }
  const Recompiler::Stats& recompiler_stats() const { return recompiler_.stats(); }
  size_t recompiler_code_bytes() const { return recompiler_.code_bytes(); }
  // The compiled blocks' direct jumps to blocks of known pcs, linked or waiting (block_links.h).
  size_t recompiler_link_sites() const { return recompiler_.link_sites(); }
  // Names the recompiler's blocks as it compiles them, in perf's map format (RecompilerT::
  // set_code_map(); null: nowhere; attached after code was compiled, it has that code compiled
  // again). The stream must outlive the console or the next call.
  void set_code_map(std::ostream* out) { recompiler_.set_code_map(out); }

  Cycles cycles() const { return sched_.now(); }
  u64 frames() const { return frames_; }
  u64 instructions() const { return cpu_.instructions(); }

  // Guest memory as the host sees it: RAM (any mirror, any segment) and the scratchpad. Host
  // accesses take no emulated time and have no side effects; other addresses throw
  // std::invalid_argument. Writes are not reported to memory watches (only guest writes are).
  u8 read8(u32 addr) const { return *host_pointer(addr, 1); }
  u16 read16(u32 addr) const;
  u32 read32(u32 addr) const;
  void write8(u32 addr, u8 v) {
    *host_pointer(addr, 1) = v;
    host_wrote(addr, 1);
  }
  void write16(u32 addr, u16 v);
  void write32(u32 addr, u32 v);
  // RAM in place. Writing code through it is not seen by the recompiler, whose blocks compiled
  // from the old code may then keep running (write8() and the others are seen). Nor are the
  // writes seen by snapshots, so once RAM or the scratchpad is lent for writing, every restore()
  // copies them back whole (Bus::lend_ram()); a reader takes the const views.
  std::span<u8> ram() {
    bus_.lend_ram();
    return {bus_.ram(), Bus::kRamSize};
  }
  std::span<u8> scratchpad() {
    bus_.lend_ram();
    return {bus_.scratchpad(), Bus::kScratchSize};
  }
  std::span<const u8> ram() const { return {bus_.ram(), Bus::kRamSize}; }
  std::span<const u8> scratchpad() const { return {bus_.scratchpad(), Bus::kScratchSize}; }
  // Writes the 2 MiB of RAM to a file (atomically).
  void dump_ram(const std::string& path) const;

  // Memory watches (memory_watch.h). Events accumulate until taken.
  void watch(const std::string& key, u32 addr, u32 length, bool fresh_only = false, u32 flow_limit_frames = 0);
  void unwatch(const std::string& key);
  void sleep_watch(const std::string& key) { watches_.sleep(key); }
  void wake_watch(const std::string& key) { watches_.wake(key); }
  std::vector<WatchEvent> take_watch_events() { return watches_.take_events(); }

  // Save states (save_state.h): the whole console. Loading checks the header against this
  // console's BIOS and program; on any error it throws StateError and the console is unchanged.
  // A successful load drops audio samples not yet taken (they belong to the abandoned timeline).
  std::vector<u8> save_state(bool compress = false);
  void load_state(const std::vector<u8>& blob);
  void save_state_file(const std::string& path, bool compress = true);
  void load_state_file(const std::string& path);

  // In-memory snapshots for fast resets (an environment returning to its start many times): the
  // console's state as it serialises it, without the save-state container's copy, checksum and
  // rollback copy. restore() accepts a snapshot of any console with the same BIOS and program
  // (others throw StateError, the console unchanged) and leaves the console as load_state()
  // would. The snapshot's buffer is reused when it is taken again.
  class Snapshot {
   public:
    bool empty() const { return payload_.empty(); }
    size_t size() const { return payload_.size(); }

   private:
    friend class Console;
    std::vector<u8> payload_;
    u64 bios_hash_ = 0;
    u64 program_hash_ = 0;
    std::shared_ptr<const void> vram_token_;  // Gpu::vram_token() when it was taken
    std::shared_ptr<const void> ram_token_;   // Bus::ram_token() when it was taken
  };
  void snapshot(Snapshot& out);
  void restore(const Snapshot& snap);

  // Video and audio for the host, without per-pixel copies. The frame is the displayed area as
  // RGB888 at its real size (e.g. 320x240) times the renderer's scale, refreshed at each VBlank;
  // the VRAM view is the GPU's 1024x512 16-bit memory. take_audio() hands over the 44.1 kHz
  // stereo samples produced since the last call by swapping buffers.
  struct Frame {
    const u8* rgb;
    u32 width;
    u32 height;
  };
  // The GPU's drawing backend: the software renderer unless replaced (e.g. by the OpenGL one,
  // gpu/gl/gl_renderer.h, whose frames are `scale` times larger). VRAM carries over.
  void set_renderer(std::unique_ptr<gpu::Renderer> renderer) { gpu_.set_renderer(std::move(renderer)); }
  // Choosing the renderer, for hosts that see only this face (environments, CLI, Python): the
  // OpenGL renderer drawing at `scale` (1 to kMaxRenderScale) times the resolution, on OSMesa
  // (headless; libOSMesa.so.8 loaded at run time unless PSXRL_OSMESA_LIBRARY names another) or on
  // the host's own `context` (a window's). False with `error` set when OpenGL is unavailable; the
  // renderer in use then stays.
  static constexpr u32 kMaxRenderScale = 8;
  bool use_gl_renderer(u32 scale, std::string& error);
  bool use_gl_renderer(std::unique_ptr<gpu::gl::GlContext> context, u32 scale, std::string& error);
  Frame frame() const { return {gpu_.display_rgb(), gpu_.display_width(), gpu_.display_height()}; }
  // The same picture at its native size whatever the renderer (observations use this one, so
  // that they do not depend on the renderer or its scale).
  Frame native_frame() const {
    const gpu::FrameOutput& d = gpu_.display();
    return {d.native_rgb(), d.native_width(), d.native_height()};
  }
  const u16* vram() const { return gpu_.vram(); }
  // Whether anything looks at pixels (on at power-on). Off, drawing waits until something reads
  // VRAM or asks for a frame, and is then done exactly as it would have been (gpu/draw_queue.h):
  // for runs whose observations are not pictures.
  void set_pixels_observed(bool observed) { gpu_.set_deferred_drawing(!observed); }
  static constexpr u32 kVramWidth = 1024, kVramHeight = 512;
  void take_audio(std::vector<StereoSample>& out) { spu_.take_samples(out); }
  // Whether anything listens (on at power-on). Off, the SPU makes no output samples (take_audio
  // gets none) and skips the mixing only they need; everything else it does stays exact
  // (spu/spu.h set_observed): for runs whose observations and move delimiting are not sound.
  void set_sound_observed(bool observed) { spu_.set_observed(observed); }
  // Whether the sound got loud, for a listener that needs no samples (spu/spu.h watch_loudness):
  // take_loud() tells whether a sample since its last call had a channel beyond `threshold` in
  // magnitude; the SPU mixes only until one has.
  void watch_loudness(std::optional<u16> threshold) { spu_.watch_loudness(threshold); }
  bool take_loud() { return spu_.take_loud(); }
  // Untaken audio is capped at one minute (the oldest half is dropped) unless the whole run's
  // audio is to be kept, e.g. for a recording.
  void keep_all_audio() { spu_.set_output_limit(SIZE_MAX); }
  // Files for the host: the displayed picture or the whole VRAM as PNG, audio as a 16-bit stereo
  // 44.1 kHz WAV. Written atomically; a failure throws InputError naming the file.
  void save_screenshot(const std::string& path) const;
  void save_vram_png(const std::string& path);
  static void save_wav(const std::string& path, const std::vector<StereoSample>& samples);

  // Text the program prints (debug ports and BIOS putchar); diagnostic messages.
  std::function<void(char)> on_tty;
  std::function<void(const std::string&)> on_log;

  Bus& bus() { return bus_; }
  Cpu& cpu() { return cpu_; }
  Gte& gte() { return gte_; }
  Scheduler& scheduler() { return sched_; }
  InterruptController& irq() { return irq_; }
  Cdrom& cdrom() { return cdrom_; }
  // Controller/memory card port: plug devices, set buttons/sticks, read rumble (sio/sio0.h).
  Sio0& sio0() { return sio0_; }
  Gpu& gpu() { return gpu_; }
  const Gpu& gpu() const { return gpu_; }
  // Sound: output samples, capture (spu/spu.h); CD audio flows CD-ROM -> cd_audio -> SPU.
  Spu& spu() { return spu_; }
  AudioFifo& cd_audio() { return cdrom_.audio_out(); }

  // Devices in the ports (configuration, not input). A digital pad is in port 1 at power-on.
  enum class PadType { None, Digital, DualShock };
  void plug_pad(int port, PadType type);
  // A 128 KiB memory card image at `path`, created on the first write and saved atomically;
  // throws InputError for a file of another size or one that cannot be read.
  void insert_memory_card(int port, const std::string& path);

  // Controller input between run calls. Ports are 1 and 2 as labelled on the console; `buttons`
  // are pad_button bits (1 = pressed). Calls for an empty port do nothing.
  void set_buttons(int port, u16 pressed);
  void press(int port, u16 buttons);
  void release(int port, u16 buttons);
  // Holds `buttons` for the next `frames` frame ends, then releases them (the seed's press and
  // release delays, in frames instead of 10 ms units).
  void press_for(int port, u16 buttons, u32 frames);
  void set_axes(int port, const AnalogAxes& axes);
  Rumble rumble(int port) const;

  void do_state(StateIO& s);

 private:
  void on_reach(u32 pc) override;
  void drop_stale_audio();
  u8* host_pointer(u32 addr, u32 width) const;
  void host_wrote(u32 addr, u32 width);
  static int port_index(int port);
  void release_timed_buttons();
  void side_load(const PsxExe& exe);
  void log(const std::string& msg) {
    if (on_log) on_log(msg);
  }

  Scheduler sched_;
  InterruptController irq_;
  Bus bus_;
  Gte gte_;
  Cpu cpu_;
  IdleSkip idle_skip_;
  Recompiler recompiler_{bus_};
  HleBios hle_;
  Cdrom cdrom_;
  Sio0 sio0_;
  Sio1 sio1_{sched_};
  Gpu gpu_;
  Spu spu_;
  Dma dma_{sched_, irq_, bus_};
  Timers timers_{sched_, irq_};
  Mdec mdec_;

  Scheduler::Handle limit_event_;
  bool frame_done_ = false;
  bool limit_reached_ = false;
  u64 frames_ = 0;
  bool hle_mode_ = false;
  std::optional<PsxExe> pending_exe_;
  std::optional<u32> exit_code_;
  std::string fatal_error_;
  MemoryWatches watches_;
  u64 bios_hash_ = 0;
  u64 program_hash_ = 0;
  // Frames left before press_for() releases each button of each port (0 = not timed).
  std::array<std::array<u32, 16>, 2> hold_frames_{};
  // Booting, running, input and save states refuse a second thread (util/thread_owner.h).
  ThreadOwner owner_{"Console"};
};

}  // namespace psx
