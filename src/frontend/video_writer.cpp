// FFmpeg video writer (video_writer.h): libavformat muxes, libavcodec encodes, libswscale turns
// the console's RGB888 into the encoder's YUV 4:2:0 (nearest pixel, so same-size pictures are
// only converted, never filtered).
#include "frontend/video_writer.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace psxrl::frontend {

bool is_video_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".mp4" || ext == ".mkv" || ext == ".mov";
}

struct VideoWriter::Impl {
  std::string path, tmp;
  AVFormatContext* fmt = nullptr;
  AVCodecContext* video = nullptr;
  AVCodecContext* audio = nullptr;
  AVStream* video_stream = nullptr;
  AVStream* audio_stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* picture = nullptr;
  AVFrame* sound = nullptr;
  AVPacket* packet = nullptr;
  std::int64_t video_pts = 0, audio_pts = 0;
  std::vector<float> left, right;  // samples waiting for a whole AAC frame
  bool finished = false;

  void check(int err, const std::string& what) const {
    if (err >= 0) return;
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(err, text, sizeof text);
    throw std::runtime_error(path + ": " + what + ": " + text);
  }
  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(path + ": " + what); }

  void open_video(const VideoFormat& f);
  void open_audio();
  void encode(AVCodecContext* codec, AVStream* stream, AVFrame* frame);
  void encode_sound(int samples);

  ~Impl() {
    sws_freeContext(sws);
    av_frame_free(&picture);
    av_frame_free(&sound);
    av_packet_free(&packet);
    avcodec_free_context(&video);
    avcodec_free_context(&audio);
    if (fmt) {
      if (fmt->pb) avio_closep(&fmt->pb);
      avformat_free_context(fmt);
    }
    std::error_code ignored;
    if (!finished && !tmp.empty()) std::filesystem::remove(tmp, ignored);
  }
};

void VideoWriter::Impl::open_video(const VideoFormat& f) {
  const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
  if (!codec) codec = avcodec_find_encoder(AV_CODEC_ID_MPEG4);
  if (!codec) fail("this FFmpeg has neither an H.264 (libx264) nor an MPEG-4 encoder");
  video = avcodec_alloc_context3(codec);
  video->width = f.width;
  video->height = f.height;
  video->pix_fmt = AV_PIX_FMT_YUV420P;
  // MPEG-4 part 2 allows time base denominators up to 65535: the closest such fraction is used.
  int num = 0, den = 0;
  av_reduce(&num, &den, f.rate.den, f.rate.num, codec->id == AV_CODEC_ID_MPEG4 ? 65535 : INT32_MAX);
  video->time_base = {num, den};
  video->framerate = {den, num};
  video->gop_size = 120;
  // 4:3 on screen whatever the pixel grid (e.g. 256x240 or 640x240 modes): the sample aspect.
  av_reduce(&video->sample_aspect_ratio.num, &video->sample_aspect_ratio.den, 4LL * f.height, 3LL * f.width, 1 << 16);
  if (codec->id == AV_CODEC_ID_MPEG4) video->bit_rate = 4'000'000;
  else av_opt_set(video->priv_data, "preset", "veryfast", 0), av_opt_set(video->priv_data, "crf", "18", 0);
  if (fmt->oformat->flags & AVFMT_GLOBALHEADER) video->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  check(avcodec_open2(video, codec, nullptr), "cannot open the video encoder");
  video_stream = avformat_new_stream(fmt, nullptr);
  if (!video_stream) fail("cannot add a video stream");
  check(avcodec_parameters_from_context(video_stream->codecpar, video), "cannot set the video stream up");
  video_stream->time_base = video->time_base;
  video_stream->avg_frame_rate = video->framerate;
  video_stream->sample_aspect_ratio = video->sample_aspect_ratio;
  picture = av_frame_alloc();
  picture->format = video->pix_fmt;
  picture->width = f.width;
  picture->height = f.height;
  check(av_frame_get_buffer(picture, 0), "cannot allocate a picture");
}

void VideoWriter::Impl::open_audio() {
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_AAC);
  if (!codec) fail("this FFmpeg has no AAC encoder");
  audio = avcodec_alloc_context3(codec);
  audio->sample_fmt = AV_SAMPLE_FMT_FLTP;  // the native AAC encoder's only format
  audio->sample_rate = 44100;
  av_channel_layout_default(&audio->ch_layout, 2);
  audio->bit_rate = 160'000;
  audio->time_base = {1, 44100};
  if (fmt->oformat->flags & AVFMT_GLOBALHEADER) audio->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  check(avcodec_open2(audio, codec, nullptr), "cannot open the AAC encoder");
  audio_stream = avformat_new_stream(fmt, nullptr);
  if (!audio_stream) fail("cannot add an audio stream");
  check(avcodec_parameters_from_context(audio_stream->codecpar, audio), "cannot set the audio stream up");
  audio_stream->time_base = audio->time_base;
  sound = av_frame_alloc();
  sound->format = audio->sample_fmt;
  sound->sample_rate = audio->sample_rate;
  sound->nb_samples = audio->frame_size;
  check(av_channel_layout_copy(&sound->ch_layout, &audio->ch_layout), "cannot set the channel layout");
  check(av_frame_get_buffer(sound, 0), "cannot allocate a sound frame");
}

void VideoWriter::Impl::encode(AVCodecContext* codec, AVStream* stream, AVFrame* frame) {
  check(avcodec_send_frame(codec, frame), "cannot encode");
  for (;;) {
    int err = avcodec_receive_packet(codec, packet);
    if (err == AVERROR(EAGAIN) || err == AVERROR_EOF) return;
    check(err, "cannot encode");
    av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    check(av_interleaved_write_frame(fmt, packet), "cannot write");
  }
}

// Encodes the first `samples` waiting samples as one frame (the last one may be shorter).
void VideoWriter::Impl::encode_sound(int samples) {
  check(av_frame_make_writable(sound), "cannot write a sound frame");
  sound->nb_samples = samples;
  std::copy_n(left.begin(), samples, reinterpret_cast<float*>(sound->data[0]));
  std::copy_n(right.begin(), samples, reinterpret_cast<float*>(sound->data[1]));
  left.erase(left.begin(), left.begin() + samples);
  right.erase(right.begin(), right.begin() + samples);
  sound->pts = audio_pts;
  audio_pts += samples;
  encode(audio, audio_stream, sound);
}

VideoWriter::VideoWriter(const std::string& path, const VideoFormat& format) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = path;
  av_log_set_level(AV_LOG_ERROR);  // encoder statistics are noise on play's output; errors stay
  if (format.width <= 0 || format.height <= 0 || format.width % 2 || format.height % 2)
    m.fail("the picture size must be even and positive (YUV 4:2:0), not " + std::to_string(format.width) + "x" +
           std::to_string(format.height));
  const AVOutputFormat* container = av_guess_format(nullptr, path.c_str(), nullptr);
  if (!container) m.fail("unknown video container (use .mp4, .mkv or .mov)");
  m.tmp = path + ".tmp";
  m.check(avformat_alloc_output_context2(&m.fmt, container, nullptr, m.tmp.c_str()), "cannot set the file up");
  m.open_video(format);
  if (format.audio) m.open_audio();
  m.packet = av_packet_alloc();
  m.check(avio_open(&m.fmt->pb, m.tmp.c_str(), AVIO_FLAG_WRITE), "cannot create " + m.tmp);
  m.check(avformat_write_header(m.fmt, nullptr), "cannot write the header");
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::add_picture(const psx::u8* rgb, int width, int height) {
  Impl& m = *impl_;
  m.sws = sws_getCachedContext(m.sws, width, height, AV_PIX_FMT_RGB24, m.video->width, m.video->height,
                               AV_PIX_FMT_YUV420P, SWS_POINT, nullptr, nullptr, nullptr);
  if (!m.sws) m.fail("cannot convert a " + std::to_string(width) + "x" + std::to_string(height) + " picture");
  m.check(av_frame_make_writable(m.picture), "cannot write a picture");
  const uint8_t* src[1] = {rgb};
  const int stride[1] = {width * 3};
  sws_scale(m.sws, src, stride, 0, height, m.picture->data, m.picture->linesize);
  m.picture->pts = m.video_pts++;
  m.encode(m.video, m.video_stream, m.picture);
}

void VideoWriter::add_audio(std::span<const psx::StereoSample> samples) {
  Impl& m = *impl_;
  if (!m.audio) return;
  for (const psx::StereoSample& s : samples) {
    m.left.push_back(static_cast<float>(s.left) / 32768.0f);
    m.right.push_back(static_cast<float>(s.right) / 32768.0f);
  }
  while (m.left.size() >= static_cast<size_t>(m.audio->frame_size)) m.encode_sound(m.audio->frame_size);
}

void VideoWriter::finish() {
  Impl& m = *impl_;
  if (m.audio) {
    // The last frame may be short only where the encoder allows it; otherwise it is padded.
    bool small_last = m.audio->codec->capabilities & AV_CODEC_CAP_SMALL_LAST_FRAME;
    if (!m.left.empty() && !small_last) {
      m.left.resize(static_cast<size_t>(m.audio->frame_size));
      m.right.resize(static_cast<size_t>(m.audio->frame_size));
    }
    if (!m.left.empty()) m.encode_sound(static_cast<int>(m.left.size()));
    m.encode(m.audio, m.audio_stream, nullptr);
  }
  m.encode(m.video, m.video_stream, nullptr);
  m.check(av_write_trailer(m.fmt), "cannot finish the file");
  m.check(avio_closep(&m.fmt->pb), "cannot close " + m.tmp);
  std::error_code err;
  std::filesystem::rename(m.tmp, m.path, err);
  if (err) m.fail("cannot rename " + m.tmp + " into place: " + err.message());
  m.finished = true;
}

std::string VideoWriter::video_codec() const { return impl_->video->codec->name; }

}  // namespace psxrl::frontend
