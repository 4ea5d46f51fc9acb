// psxrl play's per-frame front end (play_view.h).
#include "cli/play_view.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "util/png_writer.h"

namespace psxrl::cli {

namespace {

// Sound queued ahead of the speaker: enough to ride over a slow frame, short enough not to lag.
constexpr double kAudioAheadSeconds = 0.1;

}  // namespace

PlayView::PlayView(const ViewOptions& options, psx::Console& console) : options_(options), console_(console) {
  console.set_sound_observed(true);  // the speaker and recordings take every sample
  frontend::Rate rate = frontend::console_frame_rate(console);
  if (!options.record.empty())
    recorder_ = std::make_unique<frontend::Recorder>(options.record, options.record_every, rate);
  if (!options.window) return;
  psx::Console::Frame f = console.frame();
  window_ = std::make_unique<frontend::SdlWindow>(
      options.title, frontend::window_size(static_cast<int>(f.width), static_cast<int>(f.height), options.scale));
  fps_ = static_cast<double>(rate.num) / static_cast<double>(rate.den);
  pacer_.emplace(fps_);
  try {
    audio_ = std::make_unique<frontend::SdlAudio>();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "psxrl play: no sound: %s\n", e.what());
  }
}

PlayView::~PlayView() = default;

frontend::WindowInput PlayView::frame(std::span<const psx::StereoSample> audio) {
  ++frames_;
  psx::Console::Frame f = console_.frame();
  if (recorder_) recorder_->frame(f.rgb, static_cast<int>(f.width), static_cast<int>(f.height), audio);
  if (options_.max_frames && frames_ >= options_.max_frames) stopped_ = true;
  frontend::WindowInput in;
  if (!window_) return in;
  window_->show(f.rgb, static_cast<int>(f.width), static_cast<int>(f.height), !options_.window_screenshot.empty());
  if (audio_) audio_->queue(audio);
  in = window_->poll();
  if (in.save_state && on_save) on_save();
  if (in.toggle_pause) wait_while_paused(in);
  if (in.quit) stopped_ = true;
  pace();
  return in;
}

void PlayView::pace() {
  pacer_->wait_frame();
  // The sound device drains at its own clock: when the host clock runs ahead of it, wait for it
  // too, so the sound neither lags further and further nor is cut.
  while (audio_ && audio_->queued_seconds() > kAudioAheadSeconds)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void PlayView::wait_while_paused(frontend::WindowInput& in) {
  if (audio_) audio_->clear();
  window_->set_title(options_.title + " (paused: P or Space resumes)");
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(15));
    frontend::WindowInput now = window_->poll();
    if (now.save_state && on_save) on_save();
    if (now.quit || now.toggle_pause) {
      in = now;
      break;
    }
  }
  window_->set_title(options_.title);
  pacer_.emplace(fps_);  // a pause is not time to catch up on
}

std::vector<std::string> PlayView::finish() {
  std::vector<std::string> lines;
  if (recorder_) {
    recorder_->finish();
    lines.push_back("recorded " + recorder_->summary());
  }
  if (options_.window_screenshot.empty()) return lines;
  if (!window_ || window_->picture().empty()) {
    lines.push_back("no window picture to save in " + options_.window_screenshot);
    return lines;
  }
  std::string error;
  frontend::WindowSize s = window_->picture_size();
  if (!psx::write_png_rgb(options_.window_screenshot, window_->picture().data(), static_cast<psx::u32>(s.width),
                               static_cast<psx::u32>(s.height), error))
    throw std::runtime_error(error);
  lines.push_back("saved the window's last picture (" + std::to_string(s.width) + "x" + std::to_string(s.height) +
                  ") in " + options_.window_screenshot);
  return lines;
}

}  // namespace psxrl::cli
