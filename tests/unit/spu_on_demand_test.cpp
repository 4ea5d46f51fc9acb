// Sound on demand (Spu::set_observed, Console::set_sound_observed): with nothing listening the SPU
// skips the mix, but everything that is state or reaches sound RAM or the IRQ line must come out
// exactly as with the mix: save-state bytes and IRQ counts are compared against an SPU that
// mixes, on a register-driven workload (pitch-modulation chain, voices 1 and 3 in the capture
// buffers, reverb writing its work area with the IRQ address inside it, noise, CD input, one-shot
// voices setting ENDX, key off and on) and on Tumble's title and level play. A loudness watch
// (Spu::watch_loudness, for a move delimiter waiting for silence) mixes only until a loud sample:
// its flag must say what the full mix's samples say, with the same state.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "rl/env.h"
#include "spu/adpcm.h"
#include "spu_test_util.h"
#include "tumble_console_util.h"

using namespace psx;
using psx::test::Lcg;
using psx::test::SpuRig;
using psx::test::write_test_volumes_and_reverb;

namespace {

constexpr u32 kSine = 0x1000, kOneShot = 0x3000;
constexpr u32 kReverbBase = 0xFE00;  // ESA in 8-byte units: a 4 KiB work area at 7F000h
constexpr u32 kIrqAddress = 0xFE40;  // IRQA inside that work area

std::vector<u8> sine_blocks(double amplitude, size_t period, bool loop) {
  std::vector<s16> pcm(period * 28);
  for (size_t i = 0; i < pcm.size(); ++i) pcm[i] = static_cast<s16>(std::lround(amplitude * std::sin(2 * M_PI * i / period)));
  spu::AdpcmEncodeOptions o;
  o.loop = loop;
  return spu::encode_adpcm(pcm.data(), pcm.size(), o);
}

void key(SpuRig& r, u32 reg, u32 mask) {
  r.w16(reg, static_cast<u16>(mask));
  r.w16(reg + 2, static_cast<u16>(mask >> 16));
}

// Voice v: start address, pitch, volumes (bit 15 set: a sweep), ADSR.
void voice(SpuRig& r, u32 v, u32 byte_addr, u16 pitch, u16 vol_l, u16 vol_r, u16 adsr1, u16 adsr2) {
  r.voice_w(v, 0x0, vol_l);
  r.voice_w(v, 0x2, vol_r);
  r.voice_w(v, 0x4, pitch);
  r.voice_w(v, 0x6, static_cast<u16>(byte_addr / 8));
  r.voice_w(v, 0x8, adsr1);
  r.voice_w(v, 0xA, adsr2);
}

// The whole workload's registers. Reverb offsets (8-byte units) stay inside the 200h-unit area.
void set_up(SpuRig& r) {
  r.put_ram(kSine, sine_blocks(12000, 32, true));
  r.put_ram(kOneShot, sine_blocks(9000, 20, false));
  // 0: heard only in the mix; 1: captured; 2: reverb; 3: noise, captured; 4 modulates 5, which
  // modulates 6 (exponential volume sweeps); 7: one-shot with reverb (ENDX, End+Mute); 8: slow
  // attack, released by key off. Each voice the mix needs for one reason only, so that leaving
  // out any one reason changes the state.
  voice(r, 0, kSine, 0x0800, 0x3FFF, 0x2000, 0x00FF, 0x1FC0);
  voice(r, 1, kSine, 0x1000, 0x3000, 0x3000, 0x00FF, 0x1FC0);
  voice(r, 2, kSine, 0x0C00, 0x2000, 0x3FFF, 0x00FF, 0x1FC0);
  voice(r, 3, kSine, 0x1000, 0x1800, 0x1800, 0x00FF, 0x1FC0);
  voice(r, 4, kSine, 0x1800, 0x3FFF, 0x3FFF, 0x00FF, 0x1FC0);
  voice(r, 5, kSine, 0x1000, 0x3000, 0x3000, 0x00FF, 0x1FC0);
  voice(r, 6, kSine, 0x0900, 0xC01C, 0xE01C, 0x00FF, 0x1FC0);
  voice(r, 7, kOneShot, 0x1200, 0x3FFF, 0x3FFF, 0x00FF, 0x1FC0);
  voice(r, 8, kSine, 0x0A00, 0x3FFF, 0x3FFF, 0x5A3F, 0x5FD0);
  r.w16(0x1F801D90, 0x0060);  // PMON: voices 5 and 6
  r.w16(0x1F801D94, 0x0008);  // NON: voice 3
  r.w16(0x1F801D98, 0x0084);  // EON: voices 2 and 7
  write_test_volumes_and_reverb(r);
  r.w16(0x1F801DA2, kReverbBase);
  r.w16(0x1F801DA4, kIrqAddress);
  // ATTR: enable, unmute, the fastest noise clock (shift Fh, step 1: a new bit every sample, so
  // the level is a full 16-bit pattern), reverb and IRQ enable, CD input into the mix and reverb.
  r.w16(0x1F801DAA, 0xC000 | 0x3C00 | 0x0100 | 0x0080 | 0x0040 | 0x0005);
  key(r, 0x1F801D88, 0x1FF);  // KON voices 0-8
}

// Runs `n` samples with CD input; acknowledges and counts SPU IRQs (STAT bit 6) after each one.
u32 run(SpuRig& r, u32 n, u32& sample_index) {
  u32 irqs = 0;
  for (u32 i = 0; i < n; ++i, ++sample_index) {
    const s16 cd = static_cast<s16>(((sample_index * 97) % 2000) * 8 - 8000);
    r.cd.push({cd, static_cast<s16>(-cd)});
    r.run_samples(1);
    if (r.r16(0x1F801DAE) & 0x40) {
      ++irqs;
      const u16 attr = r.r16(0x1F801DAA);
      r.w16(0x1F801DAA, attr & ~0x40);
      r.w16(0x1F801DAA, attr);
    }
  }
  return irqs;
}

std::vector<u8> state_bytes(Spu& spu) {
  StateIO w;
  spu.do_state(w);
  return w.buffer();
}

// Key events during the run: voices 4 and 8 released, then 4 and the one-shot 7 keyed on again.
void events(SpuRig& r, u32 sample) {
  if (sample == 3000) key(r, 0x1F801D8C, 0x110);
  if (sample == 6000) key(r, 0x1F801D88, 0x090);
}

struct Pair {
  SpuRig heard, unheard;
  u32 index_heard = 0, index_unheard = 0;
  Pair() {
    set_up(heard);
    set_up(unheard);
    unheard.spu.set_observed(false);
  }
};

}  // namespace

TEST(SpuOnDemand, UnheardSpuKeepsStateRamAndIrqsExact) {
  auto p = std::make_unique<Pair>();
  u32 irqs_heard = 0, irqs_unheard = 0;
  for (u32 block = 0; block < 48; ++block) {
    events(p->heard, p->index_heard);
    events(p->unheard, p->index_unheard);
    irqs_heard += run(p->heard, 250, p->index_heard);
    irqs_unheard += run(p->unheard, 250, p->index_unheard);
    ASSERT_EQ(state_bytes(p->heard.spu), state_bytes(p->unheard.spu)) << "after sample " << p->index_heard;
  }
  EXPECT_EQ(irqs_heard, irqs_unheard);
  // The workload does what it is meant to exercise: reverb accesses hit IRQA (the area is
  // 1000h halfwords per side cycle, 4096 samples, so at least one hit per cycle), the one-shot
  // voice ended (ENDX bit 7), and the heard SPU made sound while the unheard one made none.
  EXPECT_GE(irqs_heard, 12000u / 4096u);
  EXPECT_NE(p->heard.r16(0x1F801D9C) & 0x80, 0);
  std::vector<StereoSample> out = p->heard.take();
  EXPECT_EQ(out.size(), 48u * 250u);
  bool loud = false;
  for (const StereoSample& s : out) loud |= s.left != 0 || s.right != 0;
  EXPECT_TRUE(loud);
  EXPECT_TRUE(p->unheard.take().empty());
}

TEST(SpuOnDemand, SwitchingListeningOnAndOffStaysExact) {
  // One SPU always heard, one heard, then not, then heard again: the state matches throughout
  // and the samples of the heard stretches are the same samples.
  auto p = std::make_unique<Pair>();
  p->unheard.spu.set_observed(true);
  for (u32 block = 0; block < 36; ++block) {
    const bool listening = block < 8 || block >= 20;
    p->unheard.spu.set_observed(listening);
    events(p->heard, p->index_heard);
    events(p->unheard, p->index_unheard);
    run(p->heard, 250, p->index_heard);
    run(p->unheard, 250, p->index_unheard);
    ASSERT_EQ(state_bytes(p->heard.spu), state_bytes(p->unheard.spu)) << "after sample " << p->index_heard;
    std::vector<StereoSample> a = p->heard.take(), b = p->unheard.take();
    ASSERT_EQ(b.size(), listening ? a.size() : 0u) << "block " << block;
    for (size_t i = 0; i < b.size(); ++i) {
      ASSERT_EQ(a[i].left, b[i].left) << "block " << block << " sample " << i;
      ASSERT_EQ(a[i].right, b[i].right) << "block " << block << " sample " << i;
    }
  }
}

TEST(SpuOnDemand, SavedStateOfAnUnheardSpuResumesHeardExactly) {
  // A state saved while unheard, loaded into an SPU that mixes, continues as the heard one does.
  auto p = std::make_unique<Pair>();
  run(p->heard, 5000, p->index_heard);
  run(p->unheard, 5000, p->index_unheard);
  std::vector<u8> saved = state_bytes(p->unheard.spu);
  SpuRig resumed;
  StateIO in(saved.data(), saved.size());
  resumed.spu.do_state(in);
  u32 resumed_index = p->index_unheard;
  p->heard.take();
  run(p->heard, 2000, p->index_heard);
  run(resumed, 2000, resumed_index);
  std::vector<StereoSample> a = p->heard.take(), b = resumed.take();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(a[i].left == b[i].left && a[i].right == b[i].right) << i;
}

// Unheard, with reverb writes (ATTR bit 7) and IRQ9 off, the reverb's values are owed until the
// output could be heard (Reverb::owe_tick). The work area starts at ESA*4 halfwords; its buffer
// address starts there when ESA is written and advances a halfword every two samples, and the
// reads lie 80h..380h halfwords past it (kTestReverbRegs), wrapping inside the area. ESA goes
// 0 (the reads pass the capture buffers, halfwords 0..7FFh, which change every sample: not
// owed), 400h (owed), FFC0h (owed; a 100h-halfword area at the end of sound RAM, so every read
// wraps and depends on ESA), and again, over sound RAM filled with noise from 2000h on. Owed values are computed when the
// output is heard again (the last 40 ticks reach it) or the state is saved (the last 128), so
// just before those moments the workload changes what they read: a transfer over 400h
// halfwords from the buffer address, a comb tap's register, ESA.
void owing_set_up(SpuRig& r) {
  set_up(r);
  Lcg noise{9};
  std::vector<u8> bytes(0x6000);
  for (u8& b : bytes) b = static_cast<u8>(noise.next(256));
  r.put_ram(0x2000, bytes);
  r.put_ram(0x7A000, bytes);
  r.w16(0x1F801DA2, 0);
  r.w16(0x1F801DAA, 0xC000 | 0x3C00 | 0x0100 | 0x0005);
}

struct OwingWorkload {
  Lcg data{5};
  u32 esa = 0, esa_sample = 0;
  void events(SpuRig& r, u32 sample) {
    const u32 attr = 0xC000 | 0x3C00 | 0x0100 | 0x0005;
    if (sample % 1500 == 1480) {
      const u32 start = esa * 4, size = 0x40000 - start;
      const u32 current = start + (sample - esa_sample) / 2 % size;
      r.w16(0x1F801DA6, static_cast<u16>(current / 4));  // TSA, in 8-byte units
      for (u32 chunk = 0; chunk < 0x20; ++chunk) {
        for (u32 i = 0; i < 0x20; ++i) r.w16(0x1F801DA8, static_cast<u16>(data.next(0x10000)));
        r.w16(0x1F801DAA, attr | 0x0010);  // manual write
        r.w16(0x1F801DAA, attr);
      }
    }
    if (sample % 1250 == 1230) r.w16(0x1F801DC0 + 2 * 12, sample % 2500 == 1230 ? 0x0020 : 0x00E0);  // mLCOMB1
    if (sample % 3000 == 1490) {
      esa = esa == 0 ? 0x400 : esa == 0x400 ? 0xFFC0 : 0;
      esa_sample = sample;
      r.w16(0x1F801DA2, static_cast<u16>(esa));
    }
  }
};

TEST(SpuOnDemand, OwedReverbValuesAreExactWhenHeard) {
  // Unheard in blocks 0-5, 12-17, ..., heard in 6-11, ...: the output is heard again at samples
  // 1500, 4500 and 7500, and the states are compared at 1250, 2500, ... A third SPU, heard, without the
  // reverb in its mix (EVOL 0), shows that the reverb's values reach the output compared.
  auto p = std::make_unique<Pair>();
  auto dry = std::make_unique<SpuRig>();
  u32 index_dry = 0;
  owing_set_up(p->heard);
  owing_set_up(p->unheard);
  owing_set_up(*dry);
  dry->w16(0x1F801D84, 0);
  dry->w16(0x1F801D86, 0);
  OwingWorkload heard, unheard, dry_work;
  bool wet = false;
  for (u32 block = 0; block < 40; ++block) {
    const bool listening = (block / 6) % 2 == 1;
    p->unheard.spu.set_observed(listening);
    for (u32 i = 0; i < 250; ++i) {
      heard.events(p->heard, p->index_heard);
      unheard.events(p->unheard, p->index_unheard);
      dry_work.events(*dry, index_dry);
      run(p->heard, 1, p->index_heard);
      run(p->unheard, 1, p->index_unheard);
      run(*dry, 1, index_dry);
    }
    std::vector<StereoSample> a = p->heard.take(), b = p->unheard.take(), d = dry->take();
    ASSERT_EQ(b.size(), listening ? a.size() : 0u) << "block " << block;
    for (size_t i = 0; i < b.size(); ++i)
      ASSERT_TRUE(a[i].left == b[i].left && a[i].right == b[i].right) << "block " << block << " sample " << i;
    for (size_t i = 0; i < a.size(); ++i) wet |= a[i].left != d[i].left || a[i].right != d[i].right;
    if (block % 5 == 4) {
      ASSERT_EQ(state_bytes(p->heard.spu), state_bytes(p->unheard.spu)) << "block " << block;
    }
  }
  EXPECT_TRUE(wet);
}

// Owed values whose reads reach the capture buffers later: ESA 0 and every read 3F000h halfwords
// past the buffer address, so at the top of sound RAM until the address reaches 1000h (8192
// ticks), then wrapped into the capture buffers. Before that, a comb tap moved to the buffer
// address itself (in the capture buffers at once) and back. Both times the values read must be
// those of their ticks.
TEST(SpuOnDemand, OwedReverbValuesReadingTheCaptureBuffersAreExact) {
  auto p = std::make_unique<Pair>();
  for (SpuRig* r : {&p->heard, &p->unheard}) {
    owing_set_up(*r);
    for (u32 reg : {0u, 1u}) r->w16(0x1F801DC0 + 2 * reg, 0);  // dAPF1, dAPF2
    for (u32 reg : {12u, 13u, 14u, 15u, 20u, 21u, 22u, 23u, 26u, 27u, 28u, 29u}) r->w16(0x1F801DC0 + 2 * reg, 0xFC00);
  }
  p->unheard.spu.set_observed(false);
  auto both = [&](u32 samples) {
    run(p->heard, samples, p->index_heard);
    run(p->unheard, samples, p->index_unheard);
  };
  both(2000);
  for (SpuRig* r : {&p->heard, &p->unheard}) r->w16(0x1F801DC0 + 2 * 12, 0);  // mLCOMB1 at the address
  both(100);
  ASSERT_EQ(state_bytes(p->heard.spu), state_bytes(p->unheard.spu)) << "comb tap moved";
  for (SpuRig* r : {&p->heard, &p->unheard}) r->w16(0x1F801DC0 + 2 * 12, 0xFC00);
  // At 9100 the buffer address is 1000h + 1C6h: the reads of the last 128 ticks lie at capture
  // buffer halfwords 186h..1C6h, the older of which the capture writes (one a sample, at the
  // sample number modulo 200h) have passed since.
  both(7000);
  ASSERT_EQ(state_bytes(p->heard.spu), state_bytes(p->unheard.spu)) << "wrapped into the capture buffers";
  p->heard.take();
  p->unheard.spu.set_observed(true);
  both(300);
  std::vector<StereoSample> a = p->heard.take(), b = p->unheard.take();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(a[i].left == b[i].left && a[i].right == b[i].right) << i;
  ASSERT_EQ(state_bytes(p->heard.spu), state_bytes(p->unheard.spu)) << "after the wrap";
}

TEST(SpuOnDemand, RunningCaptureKeepsTheMix) {
  // A recording takes the output, so an unheard SPU with a capture running still mixes it.
  auto p = std::make_unique<Pair>();
  spu::CaptureOptions o;
  p->heard.spu.start_capture(o);
  p->unheard.spu.start_capture(o);
  run(p->heard, 3000, p->index_heard);
  run(p->unheard, 3000, p->index_unheard);
  std::vector<StereoSample> a = p->heard.spu.stop_capture(), b = p->unheard.spu.stop_capture();
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(a[i].left == b[i].left && a[i].right == b[i].right) << i;
}

TEST(SpuOnDemand, TumbleTitleAndLevelPlayGiveTheSameConsoleUnheard) {
  tumble_test::TumbleConsole heard, unheard;
  unheard.console.set_sound_observed(false);
  auto both = [&](auto&& f) {
    f(heard.console);
    f(unheard.console);
  };
  std::vector<StereoSample> heard_audio, unheard_audio;
  bool sound = false;
  auto check = [&](const char* when) {
    ASSERT_EQ(heard.console.save_state(false), unheard.console.save_state(false)) << when;
    heard.console.take_audio(heard_audio);
    unheard.console.take_audio(unheard_audio);
    EXPECT_TRUE(unheard_audio.empty()) << when;
    for (const StereoSample& s : heard_audio) sound |= s.left != 0 || s.right != 0;
  };
  both([](Console& c) { c.run_frames(120); });
  check("title");
  both([](Console& c) { tumble_test::play_level_one_moves(c); });
  check("after the level-one moves");
  both([](Console& c) {
    c.press_for(1, pad_button::kLeft, 8);
    c.run_frames(60);
  });
  check("after one more move");
  EXPECT_TRUE(sound) << "Tumble made no sound: the comparison did not cover the SPU's voices";
}

TEST(SpuOnDemand, EnvironmentMixesSoundOnlyWhenSomethingTakesIt) {
  // Tumble's moves wait for silence (game.toml [moves] audio = true), so its default environment
  // hears; with that off, only an audio observation or a front end's on_frame does.
  auto heard = [](const std::string& obs, bool watch_audio, bool listener) {
    psxrl::rl::EnvConfig c;
    c.obs = obs;
    c.watch_audio = watch_audio;
    psxrl::rl::Env env(c);
    env.reset(1, 1, nullptr);
    size_t samples = 0;
    if (listener) env.on_frame = [&](std::span<const StereoSample> audio) { samples += audio.size(); };
    env.step(0);
    if (listener) {
      EXPECT_GT(samples, 0u);
    }
    return env.console().spu().observed();
  };
  EXPECT_FALSE(heard("simple", true, false));  // the delimiter watches loudness (below)
  EXPECT_FALSE(heard("simple", false, false));
  EXPECT_TRUE(heard("audio", false, false));
  EXPECT_TRUE(heard("multimodal", false, false));
  EXPECT_TRUE(heard("simple", false, true));
}

TEST(SpuOnDemand, EnvironmentDelimiterWatchesLoudness) {
  // Tumble's move delimiter needs only whether a frame got louder than its audio_threshold (64):
  // the SPU watches for that, whether or not something (an audio observation) takes the samples.
  auto threshold = [](const std::string& obs, bool watch_audio) {
    psxrl::rl::EnvConfig c;
    c.obs = obs;
    c.watch_audio = watch_audio;
    psxrl::rl::Env env(c);
    env.reset(1, 1, nullptr);
    env.step(0);
    return env.console().spu().loudness_threshold();
  };
  EXPECT_EQ(threshold("simple", true), std::optional<u16>(64));
  EXPECT_EQ(threshold("simple", false), std::nullopt);
  EXPECT_EQ(threshold("audio", true), std::optional<u16>(64));
  EXPECT_EQ(threshold("audio", false), std::nullopt);
}

TEST(SpuOnDemand, MovesEndAlikeWithSamplesTakenOrLoudnessWatched) {
  // A listener on every frame (the samples are taken, so every sample is mixed) and none (the
  // SPU mixes a frame only until its first loud sample): every move lasts the same frames and the consoles end in the same state. A
  // third environment ignores sound, to show that the moves compared include one that sound
  // kept going.
  psxrl::rl::EnvConfig c;
  c.obs = "simple";
  psxrl::rl::EnvConfig deaf_config = c;
  deaf_config.watch_audio = false;
  psxrl::rl::Env taken(c), watched(c), deaf(deaf_config);
  taken.on_frame = [](std::span<const StereoSample>) {};
  for (psxrl::rl::Env* e : {&taken, &watched, &deaf}) e->reset(1, 1, nullptr);
  bool sound_mattered = false;
  Lcg actions{7};
  int moves = 0;
  for (; moves < 30 && !sound_mattered; ++moves) {
    const int action = static_cast<int>(actions.next(4));
    const auto a = taken.step(action), b = watched.step(action), d = deaf.step(action);
    ASSERT_EQ(a.info.game_frames, b.info.game_frames) << "move " << moves;
    sound_mattered = a.info.game_frames != d.info.game_frames;
    if (a.terminated || a.truncated)
      for (psxrl::rl::Env* e : {&taken, &watched, &deaf}) e->reset(1, 2 + moves, nullptr);
  }
  EXPECT_TRUE(sound_mattered) << "in " << moves << " moves no move lasted longer for its sound";
  EXPECT_EQ(taken.console().save_state(false), watched.console().save_state(false));
}

TEST(SpuOnDemand, LoadingAStateDropsTheLoudFlag) {
  // A loud sample before a load belongs to the abandoned timeline, as untaken samples do.
  tumble_test::TumbleConsole t;
  Console& c = t.console;
  c.set_sound_observed(false);
  c.watch_loudness(0);
  const std::vector<u8> start = c.save_state(false);
  tumble_test::play_level_one_moves(c);
  c.load_state(start);
  EXPECT_FALSE(c.take_loud());
  tumble_test::play_level_one_moves(c);
  EXPECT_TRUE(c.take_loud()) << "the same play again: it was loud";
}

namespace {

// ATTR with the SPU on, unmuted and CD input mixed; AVOL and MVOL at 8000h (-1.0 as s16: CD
// volume is used as written, a fixed main volume is bits 0-14 times two, psx-spx "SPU Volume and
// ADSR Generator"), so each output sample is the CD sample negated twice: the input itself.
void cd_passthrough(SpuRig& r) {
  r.w16(0x1F801DB0, 0x8000);
  r.w16(0x1F801DB2, 0x8000);
  r.w16(0x1F801D80, 0x4000);
  r.w16(0x1F801D82, 0x4000);
  r.w16(0x1F801DAA, 0xC001);
}

// Pushes `samples` as CD input and runs them in one go (one late catch-up).
void play(SpuRig& r, const std::vector<StereoSample>& samples) {
  for (const StereoSample& s : samples) r.cd.push(s);
  r.sched.advance(Spu::kCyclesPerSample * samples.size());
  r.sched.run_due_events();
}

}  // namespace

TEST(SpuOnDemand, LoudnessIsAChannelBeyondTheThresholdInMagnitude) {
  SpuRig r;
  cd_passthrough(r);
  r.spu.set_observed(false);
  r.spu.watch_loudness(1000);
  play(r, std::vector<StereoSample>(10));  // the fixed main volume latches at the first tick
  EXPECT_FALSE(r.spu.take_loud());
  std::vector<StereoSample> quiet(300, {500, -500});
  quiet[100] = {1000, -1000}, quiet[200] = {-1000, 1000};
  play(r, quiet);
  EXPECT_FALSE(r.spu.take_loud()) << "at the threshold is not beyond it";
  for (StereoSample loud : {StereoSample{1001, 0}, StereoSample{0, -1001}, StereoSample{-1001, 0}}) {
    std::vector<StereoSample> v(300);
    v[150] = loud;
    play(r, v);
    EXPECT_TRUE(r.spu.take_loud()) << loud.left << "," << loud.right;
    EXPECT_FALSE(r.spu.take_loud()) << "taken: cleared";
  }
  EXPECT_TRUE(r.take().empty()) << "a loudness watch takes no samples";
}

TEST(SpuOnDemand, LoudnessWatchMatchesTheMixAndKeepsTheStateExact) {
  // The workload's mix (voices, pitch modulation, noise, reverb heard and writing, CD input, and
  // muted stretches) against an SPU that watches loudness: after each stretch (run late, in one catch-up, so that
  // the watch stops mixing inside it) the loud flag is what the heard samples say, and the state
  // bytes are the same.
  bool seen_loud = false, seen_quiet = false;
  for (u16 threshold : {u16{0}, u16{3000}, u16{9000}}) {
    auto p = std::make_unique<Pair>();
    p->unheard.spu.watch_loudness(threshold);
    u32 sample = 0;
    for (u32 block = 0; block < 40; ++block) {
      const u32 n = 1 + (block * 7919u) % 700;
      for (SpuRig* r : {&p->heard, &p->unheard}) {
        events(*r, block == 10 ? 3000 : block == 20 ? 6000 : 0);
        // Muted stretches (ATTR bit 14 clear): the CD input and the reverb's tail only.
        const u16 attr = r->r16(0x1F801DAA);
        r->w16(0x1F801DAA, block % 10 >= 6 ? attr & ~0x4000 : attr | 0x4000);
        std::vector<StereoSample> cd(n);
        for (u32 i = 0; i < n; ++i) cd[i] = {static_cast<s16>(((sample + i) * 97) % 2000 * 8 - 8000), 0};
        play(*r, cd);
      }
      sample += n;
      bool expected = false;
      for (const StereoSample& s : p->heard.take())
        expected |= std::abs(s.left) > threshold || std::abs(s.right) > threshold;
      const std::string where = "threshold " + std::to_string(threshold) + " block " + std::to_string(block);
      ASSERT_EQ(p->unheard.spu.take_loud(), expected) << where;
      (expected ? seen_loud : seen_quiet) = true;
      ASSERT_EQ(state_bytes(p->heard.spu), state_bytes(p->unheard.spu)) << where;
    }
    EXPECT_TRUE(p->unheard.take().empty());
  }
  EXPECT_TRUE(seen_loud && seen_quiet) << "the thresholds did not cover both outcomes";
}
