// What `psxrl play` does with each emulated frame: shows it in the window with its sound, paced
// to real time (window only), records it (--record), counts it against --frames, and handles the
// player's pause. Headless, it only records and counts. Host time is used here only: the
// emulation itself never waits on the host.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cli/pacer.h"
#include "core/console.h"
#include "frontend/recorder.h"
#include "frontend/sdl_audio.h"
#include "frontend/sdl_window.h"

namespace psxrl::cli {

struct ViewOptions {
  bool window = true;
  int scale = 0;                  // window scale; 0: frontend::window_size's default
  std::string title;
  std::string record;             // video file or PNG folder; empty: no recording
  int record_every = 1;
  std::string window_screenshot;  // PNG of the window's last picture; empty: none
  std::uint64_t max_frames = 0;   // 0: no limit
};

class PlayView {
 public:
  // Opens what `options` ask for. A window that cannot be opened throws std::runtime_error (the
  // caller falls back to headless); missing sound only prints a warning.
  PlayView(const ViewOptions& options, psx::Console& console);
  ~PlayView();

  bool has_window() const { return window_ != nullptr; }
  // The frame just emulated, with its sound. Returns the player's input; while the player has
  // paused, it waits here (still answering F5 through on_save) until resumed or quit.
  frontend::WindowInput frame(std::span<const psx::StereoSample> audio);
  // The player quit or --frames was reached: play should end.
  bool stopped() const { return stopped_; }
  std::uint64_t frames() const { return frames_; }
  // Completes the recording and writes the window screenshot; returns lines to print.
  std::vector<std::string> finish();

  std::function<void()> on_save;  // F5

 private:
  void show();
  void pace();
  void wait_while_paused(frontend::WindowInput& in);

  ViewOptions options_;
  psx::Console& console_;
  std::unique_ptr<frontend::SdlWindow> window_;
  std::unique_ptr<frontend::SdlAudio> audio_;
  std::unique_ptr<frontend::Recorder> recorder_;
  std::optional<Pacer> pacer_;
  double fps_ = 60;
  std::uint64_t frames_ = 0;
  bool stopped_ = false;
};

}  // namespace psxrl::cli
