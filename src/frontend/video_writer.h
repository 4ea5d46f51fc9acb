// Video files of play (MP4, or MKV/MOV by the file's extension) through FFmpeg's libraries:
// H.264 (libx264) when Debian's libavcodec has it, else MPEG-4 part 2, plus an AAC sound track
// of the SPU's 44.1 kHz output. Written to a temporary file renamed at finish(), so a failed or
// interrupted recording never leaves a half-written video.
#pragma once
#include <memory>
#include <span>
#include <string>

#include "core/audio_fifo.h"
#include "core/types.h"

namespace psxrl::frontend {

// Frames per second as an exact fraction.
struct Rate {
  long long num, den;
};

struct VideoFormat {
  int width = 0, height = 0;  // picture size in the file (pictures of other sizes are scaled to it)
  Rate rate{60, 1};           // pictures per second
  bool audio = true;          // an AAC track of 44.1 kHz stereo
};

// Whether `path` names a video file this writer makes (by extension: .mp4, .mkv, .mov).
bool is_video_path(const std::string& path);

class VideoWriter {
 public:
  // Opens the encoders and the temporary file; throws std::runtime_error naming the file.
  VideoWriter(const std::string& path, const VideoFormat& format);
  ~VideoWriter();  // without finish(): the temporary file is removed
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // One picture of `width` x `height` RGB888 pixels, shown for 1/rate seconds.
  void add_picture(const psx::u8* rgb, int width, int height);
  void add_audio(std::span<const psx::StereoSample> samples);
  // Flushes the encoders, writes the index and renames the file into place.
  void finish();
  // The video codec used ("libx264" or "mpeg4").
  std::string video_codec() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace psxrl::frontend
