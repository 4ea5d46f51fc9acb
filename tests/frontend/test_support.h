// Helpers of the front-end tests: running a command, reading a PNG (libpng) and asking FFmpeg's
// libavformat what a video file holds.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace psxrl::test {

struct CommandResult {
  int code = -1;
  std::string output;  // standard output and standard error together
};
CommandResult run(const std::string& command);

struct Image {
  unsigned width = 0, height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* pixel(unsigned x, unsigned y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};
// Reads a PNG as RGB888; fails the current test (and returns an empty image) when it cannot.
Image read_png(const std::filesystem::path& path);

struct VideoInfo {
  int width = 0, height = 0;
  long video_frames = 0;  // video packets in the file (one per picture)
  double frame_rate = 0;  // the video stream's average frame rate
  std::string video_codec, audio_codec;
  int sample_rate = 0, channels = 0;
  double audio_seconds = 0;  // the audio stream's duration
};
VideoInfo probe_video(const std::filesystem::path& path);

}  // namespace psxrl::test
