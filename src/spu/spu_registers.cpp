// SPU register file (psx-spx "SPU I/O Port Summary"): 16-bit registers on a 16-bit bus, with the
// documented narrow and wide access behaviour ("SPU Bus-Width").
#include <algorithm>

#include "spu/spu.h"

namespace psx {

u32 Spu::io_read(u32 offset, u32 width) {
  sync();
  offset &= kSize - 1;
  const u32 aligned = offset & ~1u;
  switch (width) {
    case 4:
      return read16(aligned) | static_cast<u32>(read16((aligned + 2) & (kSize - 1))) << 16;
    case 1:
      return (read16(aligned) >> ((offset & 1) * 8)) & 0xFF;
    default:
      return read16(aligned);
  }
}

void Spu::io_write(u32 offset, u32 value, u32 width) {
  // The samples due before the write are made with the old value (spu.h).
  sync();
  offset &= kSize - 1;
  switch (width) {
    case 4:  // two halfword writes, low first
      write16(offset & ~1u, static_cast<u16>(value));
      write16(((offset & ~1u) + 2) & (kSize - 1), static_cast<u16>(value >> 16));
      break;
    case 1:
      // 8-bit writes to odd addresses are ignored; to even addresses they act as 16-bit writes.
      if (!(offset & 1)) write16(offset, static_cast<u16>(value));
      break;
    default:
      write16(offset & ~1u, static_cast<u16>(value));
      break;
  }
}

void Spu::set_half(u32& bits, u32 offset, u16 value) {
  // Bit masks for 24 voices split over a low (voices 0-15) and a high (16-23) register.
  if (offset & 2)
    bits = (bits & 0xFFFF) | static_cast<u32>(value & 0xFF) << 16;
  else
    bits = (bits & 0xFF0000) | value;
}

u16 Spu::read_voice(u32 v, u32 reg) const {
  const spu::Voice& voice = voices_[v];
  switch (reg) {
    case 0x0: return voice.volume_left.reg();
    case 0x2: return voice.volume_right.reg();
    case 0x4: return voice.pitch;
    case 0x6: return voice.start_address;
    case 0x8: return static_cast<u16>(voice.adsr.reg());
    case 0xA: return static_cast<u16>(voice.adsr.reg() >> 16);
    case 0xC: return static_cast<u16>(voice.adsr.level());
    default: return voice.repeat_address;
  }
}

void Spu::write_voice(u32 v, u32 reg, u16 value) {
  spu::Voice& voice = voices_[v];
  switch (reg) {
    case 0x0: voice.volume_left.write(value); break;
    case 0x2: voice.volume_right.write(value); break;
    case 0x4: voice.pitch = value; break;
    case 0x6: voice.start_address = value; break;
    case 0x8: voice.adsr.set_register((voice.adsr.reg() & 0xFFFF0000u) | value); break;
    case 0xA: voice.adsr.set_register((voice.adsr.reg() & 0xFFFFu) | static_cast<u32>(value) << 16); break;
    case 0xC: voice.adsr.set_level(static_cast<s16>(value)); break;
    default: voice.write_repeat_address(value); break;
  }
}

u16 Spu::status() const {
  u16 s = attr_ & 0x3F;
  if (irq_flag_) s |= 1 << 6;
  if (attr_ & (1 << 5)) s |= 1 << 7;
  if (transfer_mode() == TransferMode::DmaWrite) s |= 1 << 8;
  if (transfer_mode() == TransferMode::DmaRead) s |= 1 << 9;
  // Bit 10 (transfer busy) stays clear: transfers complete at once here.
  if (capture_pos_ >= 0x100) s |= 1 << 11;
  return s;
}

void Spu::write_attr(u16 value) {
  attr_ = value;
  // Clearing the IRQ enable acknowledges the interrupt.
  if (!(value & kAttrIrqEnable)) irq_flag_ = false;
  if (transfer_mode() == TransferMode::ManualWrite) flush_fifo();
  // Whether a sample can raise IRQ9 depends on ATTR: the event is booked again by that rule.
  book();
}

u16 Spu::read16(u32 offset) {
  if (offset < kMVOLL) return read_voice(offset >> 4, offset & 0xF);
  if (offset >= kReverbRegs && offset < kVoiceVolumes) return reverb_.regs[(offset - kReverbRegs) / 2];
  if (offset >= kVoiceVolumes && offset < kVoiceVolumes + 4 * kNumVoices) {
    const spu::Voice& v = voices_[(offset - kVoiceVolumes) / 4];
    return static_cast<u16>((offset & 2) ? v.volume_right.level() : v.volume_left.level());
  }
  switch (offset) {
    case kMVOLL: return main_left_.reg();
    case kMVOLR: return main_right_.reg();
    case kEVOLL: return static_cast<u16>(reverb_volume_left_);
    case kEVOLR: return static_cast<u16>(reverb_volume_right_);
    case kPMON: case kPMON + 2: return static_cast<u16>(pitch_mod_ >> ((offset & 2) * 8));
    case kNON: case kNON + 2: return static_cast<u16>(noise_on_ >> ((offset & 2) * 8));
    case kEON: case kEON + 2: return static_cast<u16>(reverb_on_ >> ((offset & 2) * 8));
    case kENDX: case kENDX + 2: return static_cast<u16>(endx_ >> ((offset & 2) * 8));
    case kESA: return reverb_.base();
    case kIRQA: return irq_address_;
    case kTSA: return transfer_start_;
    case kATTR: return attr_;
    case kRAMCTRL: return ram_control_;
    case kSTAT: return status();
    case kAVOLL: return static_cast<u16>(cd_volume_left_);
    case kAVOLR: return static_cast<u16>(cd_volume_right_);
    case kBVOLL: return static_cast<u16>(ext_volume_left_);
    case kBVOLR: return static_cast<u16>(ext_volume_right_);
    case kMVOLXL: return static_cast<u16>(main_left_.level());
    case kMVOLXR: return static_cast<u16>(main_right_.level());
    default: return raw_[offset / 2];  // KON/KOFF read back the last write; unknown registers are RAM
  }
}

void Spu::write16(u32 offset, u16 value) {
  raw_[offset / 2] = value;
  if (offset < kMVOLL) return write_voice(offset >> 4, offset & 0xF, value);
  if (offset >= kReverbRegs && offset < kVoiceVolumes) {
    reverb_.settle(ram_.data());  // owed reverb values use the registers as they were
    reverb_.regs[(offset - kReverbRegs) / 2] = value;
    return;
  }
  if (offset >= kVoiceVolumes && offset < kVoiceVolumes + 4 * kNumVoices) {
    spu::Voice& v = voices_[(offset - kVoiceVolumes) / 4];
    ((offset & 2) ? v.volume_right : v.volume_left).set_level(static_cast<s16>(value));
    return;
  }
  const u32 high = (offset & 2) ? 16 : 0;
  switch (offset) {
    case kMVOLL: main_left_.write(value); break;
    case kMVOLR: main_right_.write(value); break;
    case kEVOLL: reverb_volume_left_ = static_cast<s16>(value); break;
    case kEVOLR: reverb_volume_right_ = static_cast<s16>(value); break;
    case kKON: case kKON + 2: key_on_ |= (static_cast<u32>(value) << high) & 0xFFFFFF; break;
    case kKOFF: case kKOFF + 2: key_off_ |= (static_cast<u32>(value) << high) & 0xFFFFFF; break;
    case kPMON: case kPMON + 2: set_half(pitch_mod_, offset, value), pitch_mod_ &= ~1u; break;  // voice 0 has no predecessor
    case kNON: case kNON + 2: set_half(noise_on_, offset, value); break;
    case kEON: case kEON + 2: set_half(reverb_on_, offset, value); break;
    case kESA: reverb_.settle(ram_.data()), reverb_.write_base(value); break;
    case kIRQA: irq_address_ = value; break;
    case kTSA: transfer_start_ = value, transfer_addr_ = value * 8u; break;
    case kFIFO: fifo_push(value); break;
    case kATTR: write_attr(value); break;
    case kRAMCTRL: ram_control_ = value; break;
    case kAVOLL: cd_volume_left_ = static_cast<s16>(value); break;
    case kAVOLR: cd_volume_right_ = static_cast<s16>(value); break;
    case kBVOLL: ext_volume_left_ = static_cast<s16>(value); break;
    case kBVOLR: ext_volume_right_ = static_cast<s16>(value); break;
    case kMVOLXL: main_left_.set_level(static_cast<s16>(value)); break;
    case kMVOLXR: main_right_.set_level(static_cast<s16>(value)); break;
    default: break;  // ENDX and STAT are read-only; others are plain storage (raw_)
  }
}

}  // namespace psx
