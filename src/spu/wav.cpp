// WAV reading and atomic writing (RIFF "WAVE" with a "fmt " chunk of format 1 and a "data" chunk).
#include "spu/wav.h"

#include <cstring>

#include "core/atomic_file.h"
#include "core/endian.h"
#include "core/input_error.h"

namespace psx::spu {
namespace {

void put32(std::vector<u8>& v, u32 x) {
  for (int i = 0; i < 4; ++i) v.push_back(static_cast<u8>(x >> (8 * i)));
}
void put16(std::vector<u8>& v, u16 x) {
  v.push_back(static_cast<u8>(x));
  v.push_back(static_cast<u8>(x >> 8));
}

[[noreturn]] void fail(const std::string& path, size_t offset, const std::string& what) {
  throw WavError(path + ": offset " + std::to_string(offset) + ": " + what);
}

}  // namespace

WavData read_wav(const std::string& path) {
  std::vector<u8> d;
  try {
    d = read_file(path);
  } catch (const InputError& e) {
    throw WavError(e.what());
  }
  if (d.size() < 12) fail(path, d.size(), "file ends before the 12-byte RIFF header");
  if (std::memcmp(d.data(), "RIFF", 4) != 0) fail(path, 0, "expected 'RIFF'");
  if (std::memcmp(d.data() + 8, "WAVE", 4) != 0) fail(path, 8, "expected 'WAVE'");

  WavData w;
  bool have_fmt = false;
  size_t pos = 12;
  while (pos + 8 <= d.size()) {
    const u32 size = load_le32(&d[pos + 4]);
    const size_t body = pos + 8;
    if (size > d.size() - body) fail(path, pos + 4, "chunk size " + std::to_string(size) + " runs past the end of the file");
    if (std::memcmp(&d[pos], "fmt ", 4) == 0) {
      if (size < 16) fail(path, pos + 4, "expected a 'fmt ' chunk of at least 16 bytes");
      const u16 format = load_le16(&d[body]);
      if (format != 1) fail(path, body, "expected PCM format 1, found " + std::to_string(format));
      w.channels = load_le16(&d[body + 2]);
      w.sample_rate = load_le32(&d[body + 4]);
      const u16 bits = load_le16(&d[body + 14]);
      if (w.channels == 0) fail(path, body + 2, "expected at least one channel");
      if (bits != 16) fail(path, body + 14, "expected 16 bits per sample, found " + std::to_string(bits));
      have_fmt = true;
    } else if (std::memcmp(&d[pos], "data", 4) == 0) {
      if (!have_fmt) fail(path, pos, "expected the 'fmt ' chunk before 'data'");
      const size_t frame = 2u * w.channels;
      if (size % frame != 0) fail(path, pos + 4, "data size is not a whole number of sample frames");
      w.samples.resize(size / 2);
      for (size_t i = 0; i < w.samples.size(); ++i) w.samples[i] = static_cast<s16>(load_le16(&d[body + 2 * i]));
      return w;
    }
    pos = body + size + (size & 1);  // chunks are padded to even sizes
  }
  fail(path, pos, have_fmt ? "expected a 'data' chunk" : "expected a 'fmt ' chunk");
}

void write_wav(const std::string& path, const StereoSample* samples, size_t count, u32 sample_rate) {
  const u32 data_bytes = static_cast<u32>(count * 4);
  std::vector<u8> out;
  out.reserve(44 + data_bytes);
  out.insert(out.end(), {'R', 'I', 'F', 'F'});
  put32(out, 36 + data_bytes);
  out.insert(out.end(), {'W', 'A', 'V', 'E', 'f', 'm', 't', ' '});
  put32(out, 16);
  put16(out, 1);  // PCM
  put16(out, 2);  // stereo
  put32(out, sample_rate);
  put32(out, sample_rate * 4);  // bytes per second
  put16(out, 4);                // block align
  put16(out, 16);               // bits per sample
  out.insert(out.end(), {'d', 'a', 't', 'a'});
  put32(out, data_bytes);
  for (size_t i = 0; i < count; ++i) {
    put16(out, static_cast<u16>(samples[i].left));
    put16(out, static_cast<u16>(samples[i].right));
  }

  try {
    write_file_atomically(path, out);
  } catch (const std::runtime_error& e) {
    throw WavError(e.what());
  }
}

}  // namespace psx::spu
