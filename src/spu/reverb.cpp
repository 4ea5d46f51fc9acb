// SPU reverb: the 22.05 kHz formula on the sound-RAM work area and its FIR resampling
// (psx-spx "SPU Reverb Formula", "Reverb Buffer Resampling").
#include "spu/reverb.h"

#include <algorithm>
#include <bit>

namespace psx::spu {
namespace {

// psx-spx "Reverb Buffer Resampling": the 39-tap filter used both ways.
constexpr s32 kFir[39] = {
    -0x0001, 0, 0x0002, 0, -0x000A, 0, 0x0023, 0, -0x0067, 0, 0x010A, 0, -0x0268, 0,
    0x0534,  0, -0x0B90, 0, 0x2806, 0x4000, 0x2806, 0, -0x0B90, 0, 0x0534, 0, -0x0268, 0,
    0x010A,  0, -0x0067, 0, 0x0023, 0, -0x000A, 0, 0x0002, 0, -0x0001,
};

s32 sat(s32 v) { return std::clamp(v, -0x8000, 0x7FFF); }
s32 mul(s32 a, s32 b) { return (a * b) >> 15; }

}  // namespace

void Reverb::write_base(u16 value) {
  base_ = value;
  current_ = value * 4u;
  clear_ticks_ = 0;
}

Reverb::Area::Area(u16 base, u32 current)
    : start(static_cast<s32>(base) * 4), size(0x40000 - start), offset(static_cast<s32>(current) - start) {}

s16 Reverb::read(u32 hw, const u8* ram, IrqWatch& irq) {
  if (irq.enabled && (hw >> 2) == irq.unit) irq.hit = true;
  return static_cast<s16>(ram[hw * 2] | ram[hw * 2 + 1] << 8);
}

void Reverb::write(u32 hw, s32 value, u8* ram, bool write_enable, IrqWatch& irq) {
  // With the master enable off the hardware turns the write into a read.
  if (irq.enabled && (hw >> 2) == irq.unit) irq.hit = true;
  if (!write_enable) return;
  const u16 v = static_cast<u16>(sat(value));
  ram[hw * 2] = static_cast<u8>(v);
  ram[hw * 2 + 1] = static_cast<u8>(v >> 8);
}

s32 Reverb::downsample(u32 side) const {
  // Only the even taps and the centre one are nonzero; they reach 38 inputs back.
  if (zero_inputs_ >= 39) return 0;
  const auto& h = in_history_[side];
  s32 sum = kFir[19] * h[(in_pos_ - 19) & (kRing - 1)];
  for (u32 k = 0; k < 39; k += 2) sum += kFir[k] * h[(in_pos_ - k) & (kRing - 1)];
  return sat(sum >> 15);
}

s32 Reverb::upsample(u32 side, bool fresh) const {
  // The 22.05 kHz output, zero-stuffed to 44.1 kHz and filtered (gain 2). On the cycle a new
  // value arrives the even taps apply; on the other cycle only the centre tap does.
  const auto& h = out_history_[side];
  const u32 pos = out_pos_[side];
  if (!fresh) return h[(pos - 9) & (kRing - 1)];
  s32 sum = 0;
  for (u32 j = 0; j < 20; ++j) sum += kFir[2 * j] * h[(pos - j) & (kRing - 1)];
  return sat(sum >> 14);
}

s16 Reverb::process_side(u32 side, s32 input, u32 current, u8* ram, bool we, IrqWatch& irq) {
  // The work area's bounds and position are the same for all 14 accesses of this tick.
  const Area area(base_, current);
  auto reg = [&](u32 r) { return static_cast<s32>(regs[r]) * 4; };  // 8-byte units -> halfwords
  auto vol = [&](u32 r) { return static_cast<s32>(static_cast<s16>(regs[r])); };
  auto rd = [&](s32 rel) { return static_cast<s32>(read(area.at(rel), ram, irq)); };
  const u32 other = side ^ 1;

  const s32 in = sat(mul(input, vol(vLIN + side)));
  const s32 iir = vol(vIIR);
  const s32 wall = vol(vWALL);
  // Same-side and different-side reflections: [m] = (in + [d]*vWALL - [m-2])*vIIR + [m-2].
  auto reflect = [&](u32 m_reg, u32 d_reg) __attribute__((always_inline)) {
    const s32 m = reg(m_reg);
    const s32 prev = rd(m - 1);
    const s32 x = sat(in + mul(rd(reg(d_reg)), wall) - prev);
    s32 result = sat(mul(x, iir) + prev);
    // psx-spx "Bug": with vIIR = -8000h the value written is negated.
    if (iir == -0x8000) result = -result;
    write(area.at(m), result, ram, we, irq);
  };
  // A reflection's only effects are its write and the IRQ checks of its accesses: with writes
  // off (ATTR bit 7) and no IRQ watched it changes nothing, so it is left out.
  if (we || irq.enabled) {
    reflect(mLSAME + side, dLSAME + side);
    reflect(mLDIFF + side, dLDIFF + other);
  }

  s32 out = sat((vol(vCOMB1) * rd(reg(mLCOMB1 + side)) + vol(vCOMB2) * rd(reg(mLCOMB2 + side)) +
                 vol(vCOMB3) * rd(reg(mLCOMB3 + side)) + vol(vCOMB4) * rd(reg(mLCOMB4 + side))) >> 15);
  // Two all-pass filters: out -= vAPF*[m-d]; [m] = out; out = out*vAPF + [m-d].
  auto all_pass = [&](u32 m_reg, u32 d_reg, u32 v_reg) __attribute__((always_inline)) {
    const s32 m = reg(m_reg);
    const s32 v = vol(v_reg);
    const s32 delayed = rd(m - reg(d_reg));
    out = sat(out - mul(v, delayed));
    write(area.at(m), out, ram, we, irq);
    out = sat(mul(out, v) + delayed);
  };
  all_pass(mLAPF1 + side, dAPF1, vAPF1);
  all_pass(mLAPF2 + side, dAPF2, vAPF2);
  return static_cast<s16>(out);
}

u32 Reverb::ticks_clear_of_capture() const {
  if (base_ * 4u >= kCaptureHalfwords) return UINT32_MAX;  // the area lies above them
  // process_side() without writes or an IRQ watch reads the four comb taps and the two all-pass
  // delays of its side. A read's address rises by one with the buffer address (once every two
  // ticks) until it passes 3FFFFh and wraps to the area's start: from a, t more ticks read at
  // most a + t/2.
  const Area area(base_, current_);
  auto reg = [&](u32 r) { return static_cast<s32>(regs[r]) * 4; };
  u32 ticks = UINT32_MAX;
  for (u32 side = 0; side < 2; ++side) {
    const s32 reads[6] = {reg(mLCOMB1 + side), reg(mLCOMB2 + side), reg(mLCOMB3 + side), reg(mLCOMB4 + side),
                          reg(mLAPF1 + side) - reg(dAPF1), reg(mLAPF2 + side) - reg(dAPF2)};
    for (s32 rel : reads) {
      const u32 a = area.at(rel);
      if (a < kCaptureHalfwords) return 0;
      ticks = std::min(ticks, 2 * (0x3FFFFu - a));
    }
  }
  return ticks;
}

inline void Reverb::push_input(s32 in_left, s32 in_right) {
  in_pos_ = (in_pos_ + 1) & (kRing - 1);
  in_history_[0][in_pos_] = static_cast<s16>(sat(in_left));
  in_history_[1][in_pos_] = static_cast<s16>(sat(in_right));
  zero_inputs_ = (in_left == 0 && in_right == 0) ? std::min(zero_inputs_ + 1, kRing) : 0;
}

inline u32 Reverb::moved(u32 address) const {
  // psx-spx "SPU Reverb Formula": BufferAddress = MAX(mBASE, (BufferAddress+2) AND 7FFFEh).
  return std::max<u32>(base_ * 4u, (address + 1) & 0x3FFFF);
}

inline void Reverb::step_address() { current_ = moved(current_); }

void Reverb::step_address(u32 k) {
  if (k == 0) return;
  step_address();  // from here on the address lies in mBASE*4..3FFFFh, where each step adds 1
  const u32 first = base_ * 4u, length = 0x40000 - first;  // and 3FFFFh wraps to mBASE*4
  current_ = first + (current_ - first + k - 1) % length;
}

inline void Reverb::end_tick() {
  if (phase_ == 1) step_address();
  phase_ ^= 1;
  if (clear_ticks_ > 0) --clear_ticks_;
}

void Reverb::skip_tick(s32 in_left, s32 in_right) {
  push_input(in_left, in_right);
  out_pos_[phase_] = (out_pos_[phase_] + 1) & (kRing - 1);
  end_tick();
}

void Reverb::push_zero_inputs(u32 m) {
  // Once kRing of them are in, every history entry is 0 and a push only moves in_pos_.
  u32 pushed = 0;
  for (; pushed < m && zero_inputs_ < kRing; ++pushed) push_input(0, 0);
  in_pos_ = (in_pos_ + m - pushed) & (kRing - 1);
}

void Reverb::skip_quiet(u32 m) {
  // The sides alternate, this tick's first; the buffer address moves after each right side.
  const u32 first = (m + 1) / 2, second = m / 2;
  const u32 right_ends = phase_ == 0 ? second : first;
  out_pos_[phase_] = (out_pos_[phase_] + first) & (kRing - 1);
  out_pos_[phase_ ^ 1] = (out_pos_[phase_ ^ 1] + second) & (kRing - 1);
  step_address(right_ends);
  phase_ ^= m & 1;
  clear_ticks_ = clear_ticks_ > m ? clear_ticks_ - m : 0;
}

bool Reverb::quiet_ticks(u32 n) {
  if (clear_ticks_ == 0) clear_ticks_ = ticks_clear_of_capture();
  if (clear_ticks_ < n) return false;
  // No tick reads the input history (owed values leave it out): all n inputs go in first.
  push_zero_inputs(n);
  const u32 skipped = n > kTicksToOverwrite ? n - kTicksToOverwrite : 0;
  skip_quiet(skipped);
  // The last ticks, whose values a later tick could still read: owe() with clear_ticks_ > 0 (it
  // counts down from n or more), side by side as end_tick() alternates them.
  // Each side's ticks take the next slots of its ring in turn, each owing the buffer address of
  // its tick, which moves after every right-side tick: the k-th right tick and the k-th left one
  // (k from 0) see k moves, a left tick one more where a right tick came first.
  const u32 owed = n - skipped;
  const u32 longer = (owed + 1) / 2, shorter = owed / 2;  // ticks of the side first, then the other
  const u32 count[2] = {phase_ == 0 ? longer : shorter, phase_ == 0 ? shorter : longer};
  for (u32 side = 0; side < 2; ++side) {
    u32 address = side == 0 && phase_ == 1 ? moved(current_) : current_;
    const u32 first = (out_pos_[side] + 1) & (kRing - 1);
    for (u32 k = 0, pos = first; k < count[side]; ++k, pos = (pos + 1) & (kRing - 1)) {
      owed_at_[side][pos] = address;
      address = moved(address);
    }
    out_pos_[side] = (out_pos_[side] + count[side]) & (kRing - 1);
    const u64 slots = count[side] >= kRing ? ~u64{0} : (u64{1} << count[side]) - 1;
    owed_[side] |= std::rotl(slots, static_cast<int>(first));
  }
  step_address(count[1]);
  phase_ ^= owed & 1;
  clear_ticks_ -= owed;
  return true;
}

void Reverb::owe_tick(s32 in_left, s32 in_right, u8* ram) {
  push_input(in_left, in_right);
  const u32 side = phase_;
  owe(side, out_pos_[side] = (out_pos_[side] + 1) & (kRing - 1), ram);
  end_tick();
}

void Reverb::owe(u32 side, u32 pos, u8* ram) {
  if (clear_ticks_ == 0) clear_ticks_ = ticks_clear_of_capture();
  if (clear_ticks_ == 0) {
    IrqWatch none;
    out_history_[side][pos] = process_side(side, 0, current_, ram, false, none);
    owed_[side] &= ~(u64{1} << pos);
  } else {
    owed_at_[side][pos] = current_;
    owed_[side] |= u64{1} << pos;
  }
}

void Reverb::settle(u8* ram) {
  // Nothing the owed values read has changed since their ticks, and each slot holds its latest
  // tick's, so the order does not matter.
  IrqWatch none;
  for (u32 side = 0; side < 2; ++side) {
    for (u64 left = owed_[side]; left != 0; left &= left - 1) {
      const u32 pos = static_cast<u32>(std::countr_zero(left));
      out_history_[side][pos] = process_side(side, 0, owed_at_[side][pos], ram, false, none);
    }
    owed_[side] = 0;
  }
  clear_ticks_ = 0;  // the registers or ESA may change next
}

StereoSample Reverb::tick(s32 in_left, s32 in_right, u8* ram, bool write_enable, bool want_output, IrqWatch& irq) {
  // The owed values first: this tick may read them (want_output) or write what they read.
  if (owes()) settle(ram);
  push_input(in_left, in_right);
  const u32 side = phase_;
  out_pos_[side] = (out_pos_[side] + 1) & (kRing - 1);
  out_history_[side][out_pos_[side]] = process_side(side, downsample(side), current_, ram, write_enable, irq);

  StereoSample out;
  if (want_output) {
    out.left = static_cast<s16>(upsample(0, side == 0));
    out.right = static_cast<s16>(upsample(1, side == 1));
  }
  end_tick();
  return out;
}

void Reverb::do_state(StateIO& s, u8* ram) {
  if (!s.loading() && owes()) settle(ram);
  if (s.loading()) owed_ = {}, clear_ticks_ = 0;
  s.pod(regs);
  s.pod(base_);
  s.pod(current_);
  s.pod(phase_);
  s.pod(in_pos_);
  s.pod(out_pos_);
  s.pod(in_history_);
  s.pod(out_history_);
  if (s.loading()) zero_inputs_ = 0;
  if (s.loading() && (current_ > 0x3FFFF || phase_ > 1 || in_pos_ >= kRing || out_pos_[0] >= kRing || out_pos_[1] >= kRing))
    s.fail("reverb state out of range");
}

}  // namespace psx::spu
