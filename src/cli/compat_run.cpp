// One program, one kernel, headless: boot, run, judge the final picture (compat_run.h).
#include "cli/compat_run.h"

#include <algorithm>
#include <exception>

namespace psxrl::cli {

std::uint64_t picture_hash(const psx::Console::Frame& frame) {
  std::uint64_t h = 0xCBF29CE484222325ull;  // FNV-1a 64-bit offset basis and prime
  auto mix = [&h](std::uint8_t byte) {
    h ^= byte;
    h *= 0x100000001B3ull;
  };
  for (std::uint32_t v : {frame.width, frame.height})
    for (int shift = 0; shift < 32; shift += 8) mix(static_cast<std::uint8_t>(v >> shift));
  const std::size_t bytes = std::size_t{frame.width} * frame.height * 3;
  for (std::size_t i = 0; i < bytes; ++i) mix(frame.rgb[i]);
  return h;
}

std::uint64_t distinct_colours(const psx::Console::Frame& frame) {
  const std::size_t pixels = std::size_t{frame.width} * frame.height;
  std::vector<std::uint32_t> colours(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    const psx::u8* p = frame.rgb + i * 3;
    colours[i] = std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2];
  }
  std::sort(colours.begin(), colours.end());
  return static_cast<std::uint64_t>(std::unique(colours.begin(), colours.end()) - colours.begin());
}

namespace {

// How long a BIOS may take to reach its shell entry before an EXE counts as not booted: 20 s of
// NTSC video, several times what a BIOS's intro takes.
constexpr std::uint64_t kBiosBootFrames = 1200;

// Loads the program into `console` as `psxrl run` would. Returns whether it started (Yes or No)
// or whether the BIOS is to find it on the disc itself (Unknown); throws InputError.
CompatRun::Booted boot(psx::Console& console, const CompatProgram& program, const CompatSettings& settings) {
  if (!settings.bios.empty()) console.load_bios_image(settings.bios, settings.bios_name);
  if (program.kind == CompatProgram::Kind::Exe) {
    console.boot_exe(program.path);
    return CompatRun::Booted::Yes;
  }
  console.insert_disc(program.path);
  console.boot_disc();
  return settings.bios.empty() ? CompatRun::Booted::Yes : CompatRun::Booted::Unknown;
}

void judge_stop(const psx::Console& console, CompatRun& run) {
  if (!console.fatal_error().empty()) {
    run.stop = console.fatal_error();
    run.failed = true;
  } else if (auto code = console.exit_code()) {
    run.stop = "exited with code " + std::to_string(*code);
  }
}

// Runs `frames` frames, hashing the picture after each of the last kCompatTailFrames.
void run_tail(psx::Console& console, std::uint64_t frames, CompatRun& run) {
  const std::uint64_t untimed = frames > kCompatTailFrames ? frames - kCompatTailFrames : 0;
  console.run_frames(untimed);
  for (std::uint64_t i = untimed; i < frames && !console.stopped(); ++i) {
    console.run_frame();
    run.tail_hashes.push_back(picture_hash(console.native_frame()));
  }
}

}  // namespace

std::optional<int> compat_shift(const std::vector<std::uint64_t>& a, const std::vector<std::uint64_t>& b) {
  const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
  const int min_shared = static_cast<int>(std::max(a.size(), b.size()) + 1) / 2;
  // a's index i and b's index j show the same frame of the program when both tails end on the
  // same frame: i - na == j - nb. A shift d pairs a's frame N with b's frame N + d.
  for (int m = 0; m < std::max(na, nb); ++m) {
    for (int d : {m, -m}) {
      int shared = 0;
      bool same = true;
      std::vector<std::uint64_t> seen;
      for (int i = 0; i < na && same; ++i) {
        const int j = i - na + nb + d;
        if (j < 0 || j >= nb) continue;
        same = a[i] == b[j];
        ++shared;
        if (std::find(seen.begin(), seen.end(), a[i]) == seen.end()) seen.push_back(a[i]);
      }
      if (same && shared >= min_shared && seen.size() >= 2) return d;
      if (m == 0) break;
    }
  }
  return std::nullopt;
}

CompatRun run_compat(const CompatProgram& program, const CompatSettings& settings, const std::string& screenshot) {
  CompatRun run;
  psx::Console console;
  if (settings.recompiler) console.set_cpu_mode(psx::Console::CpuMode::Recompiler);
  try {
    run.booted = boot(console, program, settings);
  } catch (const std::exception& e) {
    run.booted = CompatRun::Booted::No;
    run.stop = e.what();
    run.failed = true;
    return run;
  }
  // Headless, silent: the picture is converted when asked for at the end, the same bits.
  console.set_pixels_observed(false);
  console.set_sound_observed(false);
  // With a BIOS an EXE starts when the BIOS reaches its shell entry: the frames before that are
  // the BIOS's own, so the program's frames are counted from its start, as under the HLE kernel,
  // and the two runs end on the same frame of the program. A frame ends at a VBlank, so the
  // frame in which the BIOS hands over is the program's first, as the HLE kernel's first frame
  // is: both runs end on the program's settings.frames-th VBlank.
  std::uint64_t bios_frames = 0;
  try {
    while (console.exe_pending() && console.frames() < kBiosBootFrames && !console.stopped()) console.run_frame();
    const bool handed_over = console.frames() > 0 && !console.exe_pending();
    bios_frames = handed_over ? console.frames() - 1 : console.frames();
    if (!console.exe_pending()) run_tail(console, settings.frames - (handed_over ? 1 : 0), run);
  } catch (const std::exception& e) {
    run.stop = std::string("emulator error: ") + e.what();
    run.failed = true;
  }
  run.frames = console.frames() - bios_frames;
  if (run.stop.empty()) judge_stop(console, run);
  // An EXE still waiting for the BIOS's shell entry was never side-loaded: it did not boot.
  if (console.exe_pending()) {
    run.booted = CompatRun::Booted::No;
    run.failed = true;
    if (run.stop.empty())
      run.stop = "the BIOS did not reach its shell entry (0x80030000) to load the EXE in " +
                 std::to_string(bios_frames) + " frames";
  }
  const psx::Console::Frame frame = console.native_frame();
  run.has_picture = frame.width > 0 && frame.height > 0;
  if (!run.has_picture) return run;
  run.width = frame.width;
  run.height = frame.height;
  run.colours = distinct_colours(frame);
  run.frame_hash = picture_hash(frame);
  console.save_screenshot(screenshot);
  return run;
}

}  // namespace psxrl::cli
