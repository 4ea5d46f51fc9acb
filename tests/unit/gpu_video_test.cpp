// Video timing (psx-spx "GPU Timings": NTSC 3413 video cycles x 263 lines, PAL 3406 x 314, video
// clocks 53.693175 / 53.203425 MHz), VBlank interrupt, interlace field, display output
// conversion, PNG files and save states.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "util/png_writer.h"
#include "gpu_test_util.h"
#include "temp_files.h"

namespace psx::test {
namespace {

class Signals : public VideoSignals {
 public:
  bool wants_hblank() const override { return want_hblank; }
  void hblank_changed(bool active) override { hblanks += active; }
  void vblank_changed(bool active) override { vblanks += active; }
  void dot_clock_changed(u64 hz, u32 d) override {
    video_hz = hz;
    divider = d;
  }
  bool want_hblank = true;
  int hblanks = 0, vblanks = 0;
  u32 divider = 0;
  u64 video_hz = 0;
};

// CPU cycle of the k-th VBlank start (k from 0) when frames have `lines` lines of `per_line`
// video cycles, VBlank starting at line `first`: the video time converted to CPU cycles.
Cycles vblank_time(u64 first, u64 lines, u64 per_line, u64 hz, u64 k) {
  return (first + k * lines) * per_line * kCpuClockHz / hz;
}

TEST_F(GpuTest, NtscVblankTimesAndInterrupt) {
  std::vector<Cycles> times;
  gpu.on_vblank = [&] { times.push_back(sched.now()); };
  run(vblank_time(256, 263, 3413, 53693175, 4) + 10);
  ASSERT_EQ(times.size(), 5u);
  for (u64 k = 0; k < 5; ++k) EXPECT_EQ(times[k], vblank_time(256, 263, 3413, 53693175, k)) << k;
  EXPECT_NE(irq.stat() & (1u << static_cast<u32>(Irq::VBlank)), 0u);
}

// With nothing wanting HBlank edges the line is computed when asked. Line n (counted from
// power-on, 263 a frame) starts at n * 3413 video cycles, converted to CPU cycles and rounded
// down. Asked at uneven times, some a frame apart (many lines passed at once), some a few cycles
// apart.
TEST_F(GpuTest, LineAtAnyTimeFollowsTheVideoClock) {
  const u64 hz = 53693175;
  auto cpu_time = [&](u64 video_cycles) { return video_cycles * kCpuClockHz / hz; };
  u32 x = 12345;
  for (int probe = 0; probe < 3000; ++probe) {
    x = x * 1664525u + 1013904223u;
    run(probe % 500 == 0 ? 600000 + (x >> 12) % 10000 : 1 + (x >> 8) % 3000);
    const Cycles t = sched.now();
    u64 n = t * hz / (3413ull * kCpuClockHz);  // near the line, then exactly by the rounding
    while (cpu_time((n + 1) * 3413) <= t) ++n;
    while (cpu_time(n * 3413) > t) --n;
    ASSERT_EQ(gpu.timing().line(), n % 263) << "at cycle " << t;
  }
}

TEST_F(GpuTest, PalFrameLength) {
  gp1(0x08000008);
  std::vector<Cycles> times;
  gpu.on_vblank = [&] { times.push_back(sched.now()); };
  run(2200000);
  ASSERT_GE(times.size(), 3u);
  // 314 lines of 3406 video cycles per frame: 1069484 * 33868800 / 53203425 = 680822.x cycles.
  const u64 frame = 314ull * 3406 * kCpuClockHz;
  EXPECT_NEAR(static_cast<double>(times[2] - times[1]), static_cast<double>(frame / 53203425), 1.0);
}

TEST_F(GpuTest, SignalsCountLinesAndDotDivider) {
  Signals sig;
  gpu.set_video_signals(&sig);
  EXPECT_EQ(sig.divider, 10u);  // 256-wide mode after reset
  EXPECT_EQ(sig.video_hz, 53693175u);  // the dot clock comes from the NTSC video clock
  gp1(0x08000001);
  EXPECT_EQ(sig.divider, 8u);  // 320
  gp1(0x08000009);
  EXPECT_EQ(sig.video_hz, 53203425u);  // PAL video clock
  gp1(0x08000003);
  EXPECT_EQ(sig.divider, 4u);  // 640
  EXPECT_EQ(sig.video_hz, 53693175u);
  int start_h = 0;
  gpu.on_vblank = [&] {
    if (sig.vblanks == 1) start_h = sig.hblanks;
  };
  run(vblank_time(256, 263, 3413, 53693175, 1) + 10);
  EXPECT_EQ(sig.vblanks, 2);
  EXPECT_EQ(sig.hblanks - start_h, 263);  // one HBlank per line
  gpu.set_video_signals(nullptr);
}

// CPU cycle at which NTSC line `line` (counted from power-on, across frames) reaches video cycle
// `into` of its 3413: the video clock converted to CPU cycles, rounded down.
Cycles ntsc_line_time(u64 line, u64 into) { return (line * 3413 + into) * kCpuClockHz / 53693175; }

// HBlank edges are events only while someone wants them; the lines in between are passed lazily.
// Wanted from mid-frame on, they come at the documented times: a line's HBlank starts 2560 video
// cycles into it (GP1(06)'s default active range).
TEST_F(GpuTest, HblankEdgesWantedMidFrameComeOnTime) {
  class TimedSignals : public Signals {
   public:
    explicit TimedSignals(const Scheduler& s) : sched(s) {}
    void hblank_changed(bool active) override {
      if (active) starts.push_back(sched.now());
      Signals::hblank_changed(active);
    }
    const Scheduler& sched;
    std::vector<Cycles> starts;
  } sig(sched);
  sig.want_hblank = false;
  gpu.set_video_signals(&sig);
  run(300000);  // line 139 of the first frame (300000 * 53693175 / 33868800 / 3413 = 139.3)
  EXPECT_EQ(sig.hblanks, 0);
  EXPECT_EQ(sig.vblanks, 0);
  // At 300000 line 139 is 0.3 x 3413 = 1070 video cycles in, before its HBlank.
  ASSERT_LT(ntsc_line_time(139, 0), 300000u);
  ASSERT_GT(ntsc_line_time(139, 2560), 300000u);
  EXPECT_FALSE(gpu.video_clock().hblank_now());
  sig.want_hblank = true;
  gpu.video_clock().hblank_wanted_changed();
  run(ntsc_line_time(263 + 20, 2560) + 1 - 300000);  // to line 20 of the second frame
  // Lines 139..262, then 0..20 of the next frame: every HBlank start on time.
  ASSERT_EQ(sig.starts.size(), 263u - 139 + 21);
  for (u64 k = 0; k < sig.starts.size(); ++k) EXPECT_EQ(sig.starts[k], ntsc_line_time(139 + k, 2560)) << k;
  EXPECT_EQ(sig.vblanks, 1);
  gpu.set_video_signals(nullptr);
}

// Timer 1 counts HBlanks in closed form (VideoClock::hblanks_by, hblank_time): HBlank n (from
// 1) starts 2560 video cycles into line n - 1, at ntsc_line_time(n - 1, 2560). Asked at uneven
// times, across VBlank, with the position brought up to date in between or not.
TEST_F(GpuTest, HblankCountsAndTimesInClosedForm) {
  const auto starts_by = [](Cycles t) {
    u64 n = 0;
    while (ntsc_line_time(n, 2560) <= t) ++n;
    return n;
  };
  VideoClock& video = gpu.video_clock();
  for (Cycles t : {Cycles{0}, Cycles{1615}, Cycles{1616}, Cycles{300000}, Cycles{566107}, Cycles{1234567}}) {
    if (t > sched.now()) run(t - sched.now());
    if (t == 300000) (void)stat();  // GPUSTAT.31 brings the line position up to date
    EXPECT_EQ(video.hblanks_by(t), starts_by(t)) << t;
    EXPECT_EQ(video.hblanks_by(t + 5000), starts_by(t + 5000)) << t;
    const u64 next = video.hblanks_by(t) + 1;
    EXPECT_EQ(video.hblank_time(next), ntsc_line_time(next - 1, 2560)) << t;
    EXPECT_EQ(video.hblank_time(next + 300), ntsc_line_time(next + 299, 2560)) << t;
  }
}

TEST_F(GpuTest, InterlaceFieldToggles) {
  gp1(0x08000024);  // 480 lines, interlaced
  std::vector<u32> fields;
  gpu.on_vblank = [&] { fields.push_back((stat() >> 13) & 1); };
  run(4 * 570000);
  ASSERT_GE(fields.size(), 3u);
  EXPECT_NE(fields[0], fields[1]);
  EXPECT_NE(fields[1], fields[2]);
  gp1(0x08000000);
  EXPECT_EQ((stat() >> 13) & 1, 1u);  // always 1 without interlace
}

// GPUSTAT bits 31 (ODE) and 13 (ODE2), sampled every 200 CPU cycles (a line is about 2153).
struct FieldSample {
  bool vblank;
  u32 line, bit31, bit13;
};

class GpuFieldTest : public GpuTest {
 protected:
  std::vector<FieldSample> sample(Cycles cycles) {
    std::vector<FieldSample> out;
    for (Cycles t = 0; t < cycles; t += 200) {
      run(200);
      u32 s = stat();
      out.push_back({gpu.timing().in_vblank(), gpu.timing().line(), s >> 31, (s >> 13) & 1});
    }
    return out;
  }
  // The samples split into the visible parts of successive fields (VBlank samples dropped).
  static std::vector<std::vector<FieldSample>> visible_periods(const std::vector<FieldSample>& all) {
    std::vector<std::vector<FieldSample>> periods;
    bool in_visible = false;
    for (const FieldSample& f : all) {
      if (!f.vblank && !in_visible) periods.emplace_back();
      if (!f.vblank) periods.back().push_back(f);
      in_visible = !f.vblank;
    }
    return periods;
  }
};

TEST_F(GpuFieldTest, Interlace480Bit13IsTheFieldNotDisplayed) {
  gp1(0x08000024);  // 256x480, NTSC, interlaced
  auto all = sample(6 * 570000);
  for (const FieldSample& f : all) {
    if (f.vblank) {
      EXPECT_EQ(f.bit31, 0u) << "line " << f.line;  // psx-spx: 0 during VBlank
    }
  }
  auto periods = visible_periods(all);
  ASSERT_GE(periods.size(), 5u);
  for (size_t p = 0; p < periods.size(); ++p) {
    // 480-line mode: bit 31 changes per frame (psx-spx), and the GPU draws into the other field.
    for (const FieldSample& f : periods[p]) {
      EXPECT_EQ(f.bit31, periods[p][0].bit31) << "field " << p << " line " << f.line;
      EXPECT_EQ(f.bit13, 1 - f.bit31) << "field " << p << " line " << f.line;
    }
    if (p) {
      EXPECT_NE(periods[p][0].bit31, periods[p - 1][0].bit31) << p;
    }
  }
}

TEST_F(GpuFieldTest, Interlace240Bit31PerLineBit13PerField) {
  gp1(0x08000020);  // 256x240, NTSC, interlaced
  auto periods = visible_periods(sample(6 * 570000));
  ASSERT_GE(periods.size(), 5u);
  for (size_t p = 0; p < periods.size(); ++p) {
    const auto& v = periods[p];
    // 240-line mode: bit 31 changes per scanline (psx-spx); bit 13 holds the field all along.
    for (size_t i = 1; i < v.size(); ++i) {
      if (v[i].line != v[i - 1].line) {
        EXPECT_NE(v[i].bit31, v[i - 1].bit31) << "line " << v[i].line;
      }
      EXPECT_EQ(v[i].bit13, v[0].bit13) << "field " << p;
    }
    if (p) {
      EXPECT_NE(v[0].bit13, periods[p - 1][0].bit13) << p;
    }
  }
}

TEST_F(GpuFieldTest, ProgressiveBit13Is1AndBit31PerLine) {
  gp1(0x08000001);  // 320x240, NTSC, progressive
  auto all = sample(3 * 570000);
  for (size_t i = 1; i < all.size(); ++i) {
    EXPECT_EQ(all[i].bit13, 1u);  // psx-spx: always 1 when GP1(08h).5 = 0
    if (all[i].vblank) {
      EXPECT_EQ(all[i].bit31, 0u);
    } else if (!all[i - 1].vblank && all[i].line != all[i - 1].line) {
      EXPECT_NE(all[i].bit31, all[i - 1].bit31);
    }
  }
}

TEST_F(GpuFieldTest, BiosShellFieldSyncLoopEnds) {
  // A BIOS shell in 640x480 interlace waits for bit 31 = 1 with bit 13 = 0, then for bit 31 = 0
  // with bit 13 = 1. Three rounds take two fields each: well within 10 frames.
  gp1(0x08000027);
  Cycles limit = sched.now() + 10 * 570000;
  for (int round = 0; round < 3; ++round) {
    while (sched.now() < limit && (stat() & 0x80002000u) != 0x80000000u) run(100);
    while (sched.now() < limit && (stat() & 0x80002000u) != 0x00002000u) run(100);
  }
  EXPECT_LT(sched.now(), limit);
}

TEST_F(GpuTest, DisplayOutput15Bit) {
  poke(0, 0, 0x001F);
  poke(319, 239, 0x7C00);
  poke(320, 0, 0x03E0);  // outside the 320-wide display
  gp1(0x08000001);       // 320x240 NTSC
  gp1(0x03000000);
  run(vblank_time(256, 263, 3413, 53693175, 0) + 1);
  ASSERT_EQ(gpu.display_width(), 320u);
  ASSERT_EQ(gpu.display_height(), 240u);
  const u8* rgb = gpu.display_rgb();
  EXPECT_EQ(rgb[0], 255);
  EXPECT_EQ(rgb[1], 0);
  EXPECT_EQ(rgb[2], 0);
  const u8* last = rgb + (239 * 320 + 319) * 3;
  EXPECT_EQ(last[0], 0);
  EXPECT_EQ(last[2], 255);
  EXPECT_EQ(rgb[319 * 3 + 1], 0);
}

TEST_F(GpuTest, DisplayOutput15BitWrapsAtTheVramEdge) {
  // A 320-wide display from VRAM x = 1000 (GP1(05)) shows columns 1000..1023, then 0..295.
  // 8-bit channels are the 5-bit ones expanded: (c << 3) | (c >> 2).
  poke(1022, 0, rgb15(31, 0, 31));  // display column 22: (255, 0, 255)
  poke(1023, 0, rgb15(1, 2, 3));    // column 23: (8, 16, 24)
  poke(0, 0, rgb15(31, 16, 0));     // column 24: (255, 132, 0)
  poke(294, 0, rgb15(4, 5, 6));     // column 318: (33, 41, 49)
  poke(295, 0, 0x7FFF);             // column 319, the row's last: (255, 255, 255)
  poke(296, 0, 0x001F);             // past the display
  gp1(0x08000001);
  gp1(0x05000000 | 1000);
  gp1(0x03000000);
  run(vblank_time(256, 263, 3413, 53693175, 0) + 1);
  ASSERT_EQ(gpu.display_width(), 320u);
  const u8* rgb = gpu.display_rgb();
  const auto at = [&](u32 col) { return std::vector<int>{rgb[col * 3], rgb[col * 3 + 1], rgb[col * 3 + 2]}; };
  EXPECT_EQ(at(22), (std::vector<int>{255, 0, 255}));
  EXPECT_EQ(at(23), (std::vector<int>{8, 16, 24}));
  EXPECT_EQ(at(24), (std::vector<int>{255, 132, 0}));
  EXPECT_EQ(at(318), (std::vector<int>{33, 41, 49}));
  EXPECT_EQ(at(319), (std::vector<int>{255, 255, 255}));
  EXPECT_EQ(at(320), (std::vector<int>{0, 0, 0}));  // the next row's first pixel (VRAM (1000, 1))
}

TEST_F(GpuTest, DisplayOutputConvertsEveryColour) {
  // A 256x240 display holding every 15-bit colour, then the first 28,672 again with the mask bit
  // (bit 15) set, which the display ignores: each channel is (c << 3) | (c >> 2).
  for (u32 i = 0; i < 256 * 240; ++i) poke(i % 256, i / 256, static_cast<u16>(i & 0xFFFF));
  gp1(0x08000000);  // 256x240 NTSC
  gp1(0x03000000);
  run(vblank_time(256, 263, 3413, 53693175, 0) + 1);
  ASSERT_EQ(gpu.display_width(), 256u);
  ASSERT_EQ(gpu.display_height(), 240u);
  const u8* rgb = gpu.display_rgb();
  const auto expand = [](u32 c) { return static_cast<int>((c << 3) | (c >> 2)); };
  for (u32 i = 0; i < 256 * 240; ++i) {
    const u32 c = i & 0x7FFF;
    ASSERT_EQ(rgb[i * 3], expand(c & 31)) << i;
    ASSERT_EQ(rgb[i * 3 + 1], expand((c >> 5) & 31)) << i;
    ASSERT_EQ(rgb[i * 3 + 2], expand(c >> 10)) << i;
  }
}

TEST_F(GpuTest, DisplayOutput24BitAndDisabled) {
  gp0({0xA0000000, 0x00000000, 0x00010003, 0x44332211, 0x00006655});
  gp1(0x08000011);  // 320 wide, 24-bit
  gp1(0x03000000);
  run(vblank_time(256, 263, 3413, 53693175, 0) + 1);
  const u8* rgb = gpu.display_rgb();
  const u8 expected[6] = {0x11, 0x22, 0x33, 0x44, 0x55, 0x66};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(rgb[i], expected[i]) << i;
  gp1(0x03000001);  // display off: black
  run(vblank_time(256, 263, 3413, 53693175, 1) - sched.now() + 1);
  EXPECT_EQ(gpu.display_rgb()[0], 0);
}

TEST_F(GpuTest, PngFilesAreWrittenAtomically) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(PSXRL_BUILD_DIR) / "gpu_test_png";
  fs::create_directories(dir);
  std::string err;
  ASSERT_TRUE(gpu.write_vram_png((dir / "vram.png").string(), err)) << err;
  std::ifstream f(dir / "vram.png", std::ios::binary);
  char sig[8] = {};
  f.read(sig, 8);
  EXPECT_EQ(std::string(sig + 1, 3), "PNG");
  EXPECT_FALSE(test::temporary_files_left(dir / "vram.png"));
  EXPECT_FALSE(gpu.write_display_png((dir / "missing" / "x.png").string(), err));
  EXPECT_NE(err.find("x.png"), std::string::npos);
}

TEST_F(GpuTest, SaveStateRoundTrip) {
  gp0({0x20000000 | 0x00F800, xy(0, 0), xy(8, 0), xy(0, 8), 0xE1000205, 0xA0000000, 0x00100010, 0x00020002,
       0x12345678});  // leaves a CPU->VRAM transfer half done
  run(100000);
  StateIO w;
  sched.do_state(w);
  gpu.do_state(w);
  // The same inputs after loading give the same VRAM, status and VBlank times as before.
  auto future = [&] {
    std::vector<Cycles> vblanks;
    gpu.on_vblank = [&] { vblanks.push_back(sched.now()); };
    gp0({0x9ABCDEF0, 0x68FFFFFF, xy(50, 50)});
    run(1200000);
    std::vector<u16> v(gpu.vram(), gpu.vram() + 1024 * 512);
    v.push_back(static_cast<u16>(stat()));
    for (Cycles c : vblanks) v.push_back(static_cast<u16>(c));
    return v;
  };
  std::vector<u16> first = future();
  EXPECT_EQ(px(17, 17), 0x9ABC);  // the transfer's second word
  EXPECT_EQ(px(50, 50), 0x7FFF);
  StateIO r(w.buffer().data(), w.buffer().size());
  sched.do_state(r);
  gpu.do_state(r);
  EXPECT_TRUE(r.at_end());
  EXPECT_EQ(px(50, 50), 0);
  EXPECT_EQ(future(), first);
}

}  // namespace
}  // namespace psx::test
