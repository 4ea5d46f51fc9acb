// MDEC register file, command handling, output packing and the two DMA ports.
#include "core/mdec.h"

namespace psx {

namespace {
constexpr u32 kStatusOutEmpty = 1u << 31;
constexpr u32 kStatusLastWord = 1u << 30;
constexpr u32 kStatusBusy = 1u << 29;
constexpr u32 kStatusDataInRequest = 1u << 28;
constexpr u32 kStatusDataOutRequest = 1u << 27;
constexpr u32 kBlockCr = 4;  // status bits 16-18: 0..3 = Y1..Y4, 4 = Cr (or Y for mono)
// Most halfwords one decode command can carry (0xFFFF words) and the most words of pixels they
// can produce (two halfwords per block at the least; 24-bit macroblocks are 192 words).
constexpr size_t kMaxInput = 2 * 0xFFFF;
constexpr size_t kMaxOutput = kMaxInput / 12 * 192;
}  // namespace

Mdec::Mdec() { reset(); }

void Mdec::InPort::dma_write(const u32* words, u32 count) {
  for (u32 i = 0; i < count; ++i) m_.write_word(words[i]);
  m_.decode_available();
}

void Mdec::InPort::dma_read(u32* words, u32 count) {
  for (u32 i = 0; i < count; ++i) words[i] = 0xFFFFFFFF;  // MDECin has no data to give
}

void Mdec::OutPort::dma_read(u32* words, u32 count) {
  // DMA1 re-orders colour output into 16x16 row-major pixels (psx-spx "MDEC I/O Ports").
  for (u32 i = 0; i < count; ++i) words[i] = m_.read_data(true);
}

u32 Mdec::io_read(u32 offset, u32 width) {
  u32 v = (offset & 4) ? status() : read_data(false);
  return v >> ((offset & 3) * 8);
}

void Mdec::io_write(u32 offset, u32 value, u32 width) {
  if (!(offset & 4)) {
    write_word(value);
    decode_available();
    return;
  }
  if (value & (1u << 31)) reset();
  enable_in_ = value & (1u << 30);
  enable_out_ = value & (1u << 29);
}

u32 Mdec::status() const {
  bool out_empty = output_pos_ >= output_.size();
  u32 s = 0;
  if (out_empty) s |= kStatusOutEmpty;
  if (command_ == Command::None && !out_empty) s |= kStatusLastWord;
  if (command_ != Command::None || !out_empty) s |= kStatusBusy;
  if (data_in_request()) s |= kStatusDataInRequest;
  if (data_out_request()) s |= kStatusDataOutRequest;
  s |= ((command_word_ >> 25) & 0xF) << 23;
  u32 block = kBlockCr;
  if (!out_empty && depth() >= 2) {
    u32 per_mb = depth() == 3 ? 128 : 192;
    block = static_cast<u32>(output_pos_ % per_mb) * 4 / per_mb;
  }
  s |= block << 16;
  s |= command_ != Command::None ? (remaining_ - 1) & 0xFFFF : idle_low_;
  return s;
}

void Mdec::reset() {
  // The reset bit aborts the command but keeps the quant and scale tables (psx-spx).
  command_ = Command::None;
  command_word_ = 0;
  remaining_ = 0;
  idle_low_ = 0;  // psx-spx: reset sets status 80040000h
  input_.clear();
  input_pos_ = 0;
  output_.clear();
  output_pos_ = 0;
}

void Mdec::write_word(u32 word) {
  if (command_ == Command::None) {
    start_command(word);
    return;
  }
  input_.push_back(static_cast<u16>(word));
  input_.push_back(static_cast<u16>(word >> 16));
  if (--remaining_ > 0) return;
  if (command_ == Command::Decode) decode_available();  // ends the command
  else apply_tables();
}

void Mdec::start_command(u32 word) {
  command_word_ = word;
  input_.clear();
  input_pos_ = 0;
  idle_low_ = 0xFFFF;
  switch (word >> 29) {
    case 1:
      command_ = Command::Decode;
      remaining_ = word & 0xFFFF;
      break;
    case 2:
      command_ = Command::SetQuant;
      remaining_ = (word & 1) ? 32 : 16;  // 64 luminance bytes, then optionally 64 colour bytes
      break;
    case 3:
      command_ = Command::SetScale;
      remaining_ = 32;  // 64 signed halfwords
      break;
    default:
      // MDEC(0) and MDEC(4..7) do nothing but reflect bits 0-15 in the status register.
      command_ = Command::None;
      idle_low_ = static_cast<u16>(word);
      return;
  }
  if (remaining_ == 0) command_ = Command::None;
}

void Mdec::apply_tables() {
  if (command_ == Command::SetQuant) {
    auto byte = [this](u32 i) { return static_cast<u8>(input_[i / 2] >> ((i & 1) * 8)); };
    for (u32 i = 0; i < 64; ++i) iq_y_[i] = byte(i);
    if (command_word_ & 1)
      for (u32 i = 0; i < 64; ++i) iq_uv_[i] = byte(64 + i);
  } else {
    for (u32 i = 0; i < 64; ++i) scale_[i] = static_cast<s16>(input_[i]);
  }
  command_ = Command::None;
  input_.clear();
}

void Mdec::decode_available() {
  if (command_ != Command::Decode) return;
  while (decode_macroblock()) {
  }
  input_.erase(input_.begin(), input_.begin() + static_cast<std::ptrdiff_t>(input_pos_));
  input_pos_ = 0;
  if (remaining_ == 0) {
    // All parameters are in: an incomplete trailing block (or FE00h padding) is dropped.
    command_ = Command::None;
    input_.clear();
  }
}

bool Mdec::decode_macroblock() {
  const u16* src = input_.data();
  size_t size = input_.size();
  size_t pos = input_pos_;
  mdec::Block blk;
  if (depth() >= 2) {
    // Colour: Cr, Cb (colour quant table), then Y1..Y4 (luminance table), each through the IDCT.
    mdec::Samples cr, cb, y;
    mdec::Rgb16x16 rgb;
    if (!mdec::rl_decode_block(src, size, pos, iq_uv_, blk)) return false;
    mdec::idct(scale_, blk, cr);
    if (!mdec::rl_decode_block(src, size, pos, iq_uv_, blk)) return false;
    mdec::idct(scale_, blk, cb);
    for (u32 b = 0; b < 4; ++b) {
      if (!mdec::rl_decode_block(src, size, pos, iq_y_, blk)) return false;
      mdec::idct(scale_, blk, y);
      mdec::yuv_to_rgb(cr, cb, y, (b & 1) * 8, (b >> 1) * 8, depth() == 3, rgb);
    }
    pack_colour(rgb);
  } else {
    mdec::Samples y;
    if (!mdec::rl_decode_block(src, size, pos, iq_y_, blk)) return false;
    mdec::idct(scale_, blk, y);
    pack_mono(y);
  }
  input_pos_ = pos;
  return true;
}

void Mdec::pack_colour(const mdec::Rgb16x16& rgb) {
  bool is_signed = command_word_ & (1u << 26);
  if (depth() == 3) {
    // 15-bit: bit 15 comes from command bit 25 (psx-spx "MDEC(1)").
    u32 stp = (command_word_ >> 25) & 1;
    auto pixel = [&](u32 p) { return static_cast<u32>(mdec::rgb15(&rgb[p * 3], is_signed)) | stp << 15; };
    for (u32 p = 0; p < 256; p += 2) output_.push_back(pixel(p) | pixel(p + 1) << 16);
    return;
  }
  u32 flip = is_signed ? 0x80808080 : 0;  // 24-bit: R, G, B bytes back to back
  for (u32 i = 0; i < rgb.size(); i += 4)
    output_.push_back((rgb[i] | rgb[i + 1] << 8 | rgb[i + 2] << 16 | static_cast<u32>(rgb[i + 3]) << 24) ^ flip);
}

void Mdec::pack_mono(const mdec::Samples& y) {
  bool is_signed = command_word_ & (1u << 26);
  if (depth() == 1) {
    for (u32 i = 0; i < 64; i += 4) {
      u32 w = 0;
      for (u32 j = 0; j < 4; ++j) w |= static_cast<u32>(mdec::mono8(y[i + j], is_signed)) << (8 * j);
      output_.push_back(w);
    }
    return;
  }
  for (u32 i = 0; i < 64; i += 8) {  // 4-bit: first pixel in the low nibble
    u32 w = 0;
    for (u32 j = 0; j < 8; ++j) w |= static_cast<u32>(mdec::mono4(y[i + j], is_signed)) << (4 * j);
    output_.push_back(w);
  }
}

u32 Mdec::read_data(bool dma_order) {
  if (output_pos_ >= output_.size()) return 0;  // nothing decoded: the bus sees no data
  size_t idx = output_pos_;
  if (!dma_order && depth() >= 2) {
    // The register gives colour output as four 8x8 blocks (Y1..Y4), each row-major; the
    // buffer holds 16x16 row-major words (rw words per 8-pixel row).
    u32 per_mb = depth() == 3 ? 128 : 192;
    u32 rw = per_mb / 32;
    u32 i = static_cast<u32>(idx % per_mb);
    u32 block = i / (per_mb / 4), w = i % (per_mb / 4);
    u32 row = w / rw + (block >= 2 ? 8 : 0);
    u32 col = w % rw + ((block & 1) ? rw : 0);
    idx = idx - i + row * 2 * rw + col;
  }
  u32 v = output_[idx];
  if (++output_pos_ == output_.size()) {
    output_.clear();
    output_pos_ = 0;
  }
  return v;
}

void Mdec::do_state(StateIO& s) {
  s.section("MDEC", 1);
  u32 cmd = static_cast<u32>(command_);
  s.pod(cmd);
  if (s.loading() && cmd > 3) s.fail("bad MDEC command state " + std::to_string(cmd));
  command_ = static_cast<Command>(cmd);
  s.pod(command_word_);
  s.pod(remaining_);
  s.pod(idle_low_);
  s.boolean(enable_in_);
  s.boolean(enable_out_);
  s.vec(input_, kMaxInput);
  u64 in_pos = input_pos_, out_pos = output_pos_;
  s.pod(in_pos);
  s.vec(output_, kMaxOutput);
  s.pod(out_pos);
  if (s.loading() && (in_pos > input_.size() || out_pos > output_.size()))
    s.fail("MDEC FIFO position past its contents");
  input_pos_ = in_pos;
  output_pos_ = out_pos;
  s.pod(iq_y_);
  s.pod(iq_uv_);
  s.pod(scale_);
  s.end_section("MDEC");
}

}  // namespace psx
