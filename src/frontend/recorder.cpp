// Recording of play (recorder.h).
#include "frontend/recorder.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "core/console.h"
#include "util/png_writer.h"

namespace psxrl::frontend {

Rate console_frame_rate(const psx::Console& console) {
  using T = psx::gpu::VideoTiming;
  const T& t = console.gpu().timing();
  long long per_frame = t.pal() ? static_cast<long long>(T::kPalCyclesPerLine) * T::kPalLines
                                : static_cast<long long>(T::kNtscCyclesPerLine) * T::kNtscLines;
  return {static_cast<long long>(t.video_hz()), per_frame};
}

Recorder::Recorder(const std::string& target, int every, Rate rate)
    : target_(target), every_(every), rate_(rate), video_(is_video_path(target)) {
  if (every < 1)
    throw std::invalid_argument("pictures are recorded 1 in N frames, N at least 1, not " + std::to_string(every));
  if (video_) {
    // The file is opened at the first picture, whose size it takes; an unwritable place is found
    // out now, before anything is played.
    std::string probe = target + ".tmp";
    std::FILE* f = std::fopen(probe.c_str(), "wb");
    if (!f) throw std::runtime_error(target + ": cannot create the video file: " + std::strerror(errno));
    std::fclose(f);
    std::remove(probe.c_str());
    return;
  }
  std::error_code err;
  std::filesystem::create_directories(target, err);
  if (err || !std::filesystem::is_directory(target))
    throw std::runtime_error(target + ": cannot create the folder for recorded pictures" +
                             (err ? ": " + err.message() : std::string()));
}

Recorder::~Recorder() = default;

void Recorder::frame(const psx::u8* rgb, int width, int height, std::span<const psx::StereoSample> audio) {
  bool keep = frames_ % static_cast<std::uint64_t>(every_) == 0;
  ++frames_;
  if (video_ && !writer_) {
    // YUV 4:2:0 needs even sizes; the console's displayed areas (256 to 640 wide, 240 or 480
    // lines, psx-spx "GPU Display Control") always are, so this rounds only odd custom ranges.
    width_ = (width + 1) & ~1;
    height_ = (height + 1) & ~1;
    VideoFormat format{width_, height_, {rate_.num, rate_.den * every_}, true};
    writer_ = std::make_unique<VideoWriter>(target_, format);
  }
  if (writer_) writer_->add_audio(audio);
  else audio_.insert(audio_.end(), audio.begin(), audio.end());
  if (!keep) return;
  ++pictures_;
  if (writer_) {
    writer_->add_picture(rgb, width, height);
    return;
  }
  char name[32];
  std::snprintf(name, sizeof name, "frame%06llu.png", static_cast<unsigned long long>(frames_));
  std::string error;
  if (!psx::write_png_rgb((std::filesystem::path(target_) / name).string(), rgb, static_cast<psx::u32>(width),
                               static_cast<psx::u32>(height), error))
    throw std::runtime_error(error);
  width_ = width;
  height_ = height;
}

void Recorder::finish() {
  if (writer_) writer_->finish();
  else if (!video_) psx::Console::save_wav((std::filesystem::path(target_) / "audio.wav").string(), audio_);
}

std::string Recorder::summary() const {
  std::string size = std::to_string(width_) + "x" + std::to_string(height_);
  if (video_) {
    std::string codec = writer_ ? writer_->video_codec() + " + AAC" : "nothing recorded";
    return std::to_string(pictures_) + " pictures (" + size + ", " + codec + ") in " + target_;
  }
  return std::to_string(pictures_) + " PNG pictures (" + size + ") and audio.wav in " + target_;
}

}  // namespace psxrl::frontend
