// Recording what play shows: every Nth picture to a video file (video_writer.h) with the whole
// sound track, or to numbered PNG files in a folder with the sound beside them as audio.wav.
#pragma once
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/audio_fifo.h"
#include "core/types.h"
#include "frontend/video_writer.h"

namespace psx {
class Console;
}

namespace psxrl::frontend {

// The console's frames per second (psx-spx "GPU Timings": video clock / (cycles per line x lines
// per frame), 53693175 / (3413 x 263) = 59.82 Hz NTSC, 53203425 / (3406 x 314) = 49.75 Hz PAL;
// interlaced fields are half a line shorter, which this ignores).
Rate console_frame_rate(const psx::Console& console);

class Recorder {
 public:
  // `target`: a .mp4/.mkv/.mov file, or a folder (created if missing) for PNG pictures.
  // `every`: pictures kept, 1 in N (the first is always kept). `rate`: the console's frames per
  // second, so a video plays at the console's speed. Throws std::runtime_error naming the target.
  Recorder(const std::string& target, int every, Rate rate);
  ~Recorder();

  // One emulated frame: its picture (RGB888) and the sound produced during it.
  void frame(const psx::u8* rgb, int width, int height, std::span<const psx::StereoSample> audio);
  // Completes the files (the video is renamed into place, audio.wav written).
  void finish();
  // What was written, e.g. "60 pictures (320x240, libx264 + AAC) in out.mp4".
  std::string summary() const;

 private:
  std::string target_;
  int every_;
  Rate rate_;
  bool video_;
  std::unique_ptr<VideoWriter> writer_;
  std::vector<psx::StereoSample> audio_;  // for audio.wav beside PNG pictures
  std::uint64_t frames_ = 0, pictures_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace psxrl::frontend
