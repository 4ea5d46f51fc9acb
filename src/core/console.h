// The emulated PlayStation and the emulator's only public face: every hardware block lives here,
// wired together, on one scheduler timeline. Environments, Lua, Python and the CLI use nothing
// else from the core. A console is self-contained (no global state): many can run on many
// threads. It never starts threads itself; every run call returns synchronously.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/bios/exe.h"
#include "core/bios/hle_bios.h"
#include "core/bus.h"
#include "core/cpu/cpu.h"
#include "core/dma.h"
#include "core/gte/gte.h"
#include "core/irq.h"
#include "core/mdec.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/timers.h"

namespace psx {

class Console : private CpuHooks {
 public:
  // PS-X EXE shell entry: with a real BIOS, EXEs are side-loaded when the BIOS gets here.
  static constexpr u32 kShellEntry = 0x80030000;
  // Until video timing exists a frame is this many CPU cycles (33868800 / 60).
  static constexpr Cycles kFrameCycles = kCpuClockHz / 60;

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
  // Boots the BIOS alone (from reset), e.g. for a BIOS test or a disc.
  void boot_bios();

  // Runs to the end of the current frame (or until the program stops the console).
  void run_frame();
  void run_frames(u64 n);
  void run_cycles(Cycles n);

  // The program wrote its exit code to the debug port, or the console hit a fatal guest error.
  bool stopped() const { return exit_code_.has_value() || !fatal_error_.empty(); }
  std::optional<u32> exit_code() const { return exit_code_; }
  const std::string& fatal_error() const { return fatal_error_; }

  Cycles cycles() const { return sched_.now(); }
  u64 frames() const { return frames_; }
  u64 instructions() const { return cpu_.instructions(); }

  // Text the program prints (debug ports and BIOS putchar); diagnostic messages.
  std::function<void(char)> on_tty;
  std::function<void(const std::string&)> on_log;

  Bus& bus() { return bus_; }
  Cpu& cpu() { return cpu_; }
  Gte& gte() { return gte_; }
  Scheduler& scheduler() { return sched_; }
  InterruptController& irq() { return irq_; }

  void do_state(StateIO& s);

 private:
  void on_reach(u32 pc) override;
  void side_load(const PsxExe& exe);
  void log(const std::string& msg) {
    if (on_log) on_log(msg);
  }

  Scheduler sched_;
  InterruptController irq_;
  Bus bus_;
  Gte gte_;
  Cpu cpu_;
  HleBios hle_;
  // DMA, root counters, MDEC (issue 5).
  Dma dma_{sched_, irq_, bus_};
  Timers timers_{sched_, irq_};
  Mdec mdec_;

  Scheduler::Handle frame_event_;
  Scheduler::Handle limit_event_;
  bool frame_done_ = false;
  bool limit_reached_ = false;
  u64 frames_ = 0;
  bool hle_mode_ = false;
  std::optional<PsxExe> pending_exe_;
  std::optional<u32> exit_code_;
  std::string fatal_error_;
};

}  // namespace psx
