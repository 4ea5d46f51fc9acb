// Helpers of the front-end tests (test_support.h).
#include "test_support.h"

#include <gtest/gtest.h>
#include <png.h>
#include <sys/wait.h>

#include <cstdio>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

namespace psxrl::test {

CommandResult run(const std::string& command) {
  CommandResult r;
  std::FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

Image read_png(const std::filesystem::path& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  Image img;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    ADD_FAILURE() << path << ": " << png.message;
    return img;
  }
  png.format = PNG_FORMAT_RGB;
  img.rgb.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, img.rgb.data(), 0, nullptr)) {
    ADD_FAILURE() << path << ": " << png.message;
    img.rgb.clear();
    return img;
  }
  img.width = png.width;
  img.height = png.height;
  return img;
}

VideoInfo probe_video(const std::filesystem::path& path) {
  VideoInfo v;
  AVFormatContext* fmt = nullptr;
  if (avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) < 0 || avformat_find_stream_info(fmt, nullptr) < 0) {
    ADD_FAILURE() << path << ": FFmpeg cannot read it";
    avformat_close_input(&fmt);
    return v;
  }
  int video = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  int audio = av_find_best_stream(fmt, AVMEDIA_TYPE_AUDIO, -1, -1, nullptr, 0);
  if (video >= 0) {
    const AVStream* s = fmt->streams[video];
    v.width = s->codecpar->width;
    v.height = s->codecpar->height;
    v.frame_rate = av_q2d(s->avg_frame_rate);
    v.video_codec = avcodec_get_name(s->codecpar->codec_id);
  }
  if (audio >= 0) {
    const AVStream* s = fmt->streams[audio];
    v.audio_codec = avcodec_get_name(s->codecpar->codec_id);
    v.sample_rate = s->codecpar->sample_rate;
    v.channels = s->codecpar->ch_layout.nb_channels;
    v.audio_seconds = static_cast<double>(s->duration) * av_q2d(s->time_base);
  }
  AVPacket* pkt = av_packet_alloc();
  while (av_read_frame(fmt, pkt) >= 0) {
    v.video_frames += pkt->stream_index == video;
    av_packet_unref(pkt);
  }
  av_packet_free(&pkt);
  avformat_close_input(&fmt);
  return v;
}

}  // namespace psxrl::test
