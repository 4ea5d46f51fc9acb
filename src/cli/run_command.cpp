// `psxrl run`: boots a PS-X EXE (with a BIOS or the HLE kernel), a disc, or a BIOS alone headless,
// prints the program's TTY output, and exits with the program's exit code or when the frame/cycle
// limit is reached, with a summary of the run on standard error (run_summary.h).
#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli.h"
#include "cli/input_script.h"
#include "cli/options.h"
#include "cli/pacer.h"
#include "cli/renderer_option.h"
#include "cli/run_summary.h"
#include "core/console.h"

namespace psxrl::cli {

namespace {

const char* kRunFooter =
    "With --bios and no --exe or --disc, the BIOS starts from reset with no disc (its shell).\n"
    "\n"
    "exit codes:\n"
    "  the program's own exit code (written to 0x1F802082; values above 255 exit as 255)\n"
    "  0  the limit was reached (without --expect-exit)\n"
    "  1  usage error\n"
    "  2  bad input file, or --renderer gl without a working OpenGL (OSMesa)\n"
    "  3  the program failed (fatal guest error) or timed out under --expect-exit\n";

// What each option's value must be, for the message when it is missing.
const std::map<std::string, std::string> kRunNeeds = {
    {"--exe", "a file"}, {"--disc", "a file"}, {"--bios", "a file"}, {"--frames", "a whole number"},
    {"--cycles", "a positive whole number"}, {"--screenshot", "a file"}, {"--vram", "a file"},
    {"--wav", "a file"}, {"--input", "a file"}, {"--screenshot-at", "a frame number and a file"},
    {"--pad1", "digital, dualshock or none"}, {"--pad2", "digital, dualshock or none"},
    {"--memcard1", "a file"}, {"--memcard2", "a file"}, {"--renderer", "software or gl"}, {"--scale", "1 to 8"},
    {"--cpu", "interpreter or recompiler"}};

bool parse_count(const std::string& s, unsigned long long& out) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) return false;
  try {
    out = std::stoull(s);
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

bool parse_pad(const std::string& s, psx::Console::PadType& out) {
  if (s == "digital") out = psx::Console::PadType::Digital;
  else if (s == "dualshock") out = psx::Console::PadType::DualShock;
  else if (s == "none") out = psx::Console::PadType::None;
  else return false;
  return true;
}

struct ScreenshotAt {
  unsigned long long frame;
  std::string path;
};

// Runs `frames` frames one at a time, pressing the script's buttons on port 1 before the frame
// each is due in and writing the screenshots due when a frame ends (adding them to `written`),
// paced to real time when a pacer is given. A screenshot that cannot be written throws InputError.
void run_scripted(psx::Console& console, unsigned long long frames, const std::vector<InputPress>& presses,
                  const std::vector<ScreenshotAt>& shots, Pacer* pacer, std::vector<std::string>& written) {
  size_t next_press = 0;
  for (unsigned long long f = 0; f < frames && !console.stopped(); ++f) {
    for (; next_press < presses.size() && presses[next_press].frame == f; ++next_press)
      console.press_for(1, presses[next_press].buttons, presses[next_press].hold);
    console.run_frame();
    if (pacer) pacer->wait_frame();
    for (const ScreenshotAt& shot : shots)
      if (shot.frame == f) {
        console.save_screenshot(shot.path);
        written.push_back(shot.path);
      }
  }
}

// psxrl run's options as given on the command line, before they are checked.
struct RunArgs {
  std::string exe, bios, disc, screenshot, vram_png, wav, input_path;
  std::string frames_text = "3600", cycles_text, pad_text[2] = {"digital", "none"};
  std::string memcards[2];
  std::string cpu = "interpreter";
  std::vector<std::pair<std::string, std::string>> shot_args;
  bool expect_exit = false, quiet = false, realtime = false, no_idle_skip = false;
  RendererArgs render;

  void add_to(CLI::App& app) {
    app.add_option("--exe", exe, "PS-X EXE to run")->type_name("FILE");
    app.add_option("--disc", disc, "disc image (.cue, .iso or a raw .bin) to insert; without --exe it is booted\n"
                                   "(with --bios by the BIOS itself from reset, as on the console)")->type_name("FILE");
    app.add_option("--bios", bios, "BIOS image (exactly 512 KiB); without it the HLE kernel is used")->type_name("FILE");
    app.add_option("--frames", frames_text, "stop after N frames (default 3600)")->type_name("N");
    app.add_option("--cycles", cycles_text, "stop after N CPU cycles (instead of --frames)")->type_name("N");
    app.add_flag("--expect-exit", expect_exit, "reaching the limit is a failure (exit 3): the program must exit itself");
    app.add_flag("--quiet", quiet, "no summary or diagnostics on standard error");
    app.add_flag("--realtime", realtime, "run no faster than the console (59.94 frames per second), to watch");
    app.add_flag("--no-idle-skip", no_idle_skip,
                 "interpret loops that wait for the next event instead of skipping them (same results, slower)");
    app.add_option("--cpu", cpu,
                   "CPU core: interpreter (default, the reference) or recompiler (x86-64 code compiled per\n"
                   "block; the same results, cycle for cycle)")->type_name("CORE");
    app.add_option("--pad1", pad_text[0], "controller in port 1: digital (default), dualshock or none")->type_name("TYPE");
    app.add_option("--pad2", pad_text[1], "controller in port 2: none (default), digital or dualshock")->type_name("TYPE");
    app.add_option("--memcard1", memcards[0], "memory card in slot 1 (raw 128 KiB image; created on the first write)")
        ->type_name("FILE");
    app.add_option("--memcard2", memcards[1], "memory card in slot 2")->type_name("FILE");
    app.add_option("--screenshot", screenshot, "write the displayed picture as PNG at the end of the run")->type_name("FILE");
    app.add_option("--vram", vram_png, "write all of VRAM (1024x512) as PNG at the end of the run")->type_name("FILE");
    app.add_option("--wav", wav, "write the whole run's audio (stereo 16-bit, 44.1 kHz) to FILE")->type_name("FILE");
    app.add_option("--input", input_path,
                   "press port 1's buttons from a script: one line per press, FRAME BUTTONS [HOLD_FRAMES],\n"
                   "frames counted from 0, BUTTONS joined by '+' from up down left right cross circle\n"
                   "square triangle l1 l2 r1 r2 start select l3 r3, HOLD_FRAMES default 1, '#' comments")
        ->type_name("FILE");
    app.add_option("--screenshot-at", shot_args,
                   "write the displayed picture as PNG when frame FRAME (counted from 0) ends;\n"
                   "repeatable; needs --frames above FRAME")
        ->type_name("FRAME FILE")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    render.add_to(app, "with --renderer gl: draw at N times the resolution, 1 to 8 (default 1); screenshots\n"
                       "are N times larger, --vram stays 1024x512");
  }
};

}  // namespace

int run_command(const std::vector<std::string>& args) {
  CLI::App app{"Runs a PlayStation program headless and prints what it writes to the TTY (debug port\n"
               "0x1F802080, DUART 0x1F802023, BIOS putchar).",
               "psxrl run"};
  setup_app(app, kRunFooter);
  RunArgs a;
  a.add_to(app);
  if (auto code = parse_args(app, args, kRunNeeds)) return *code;
  const std::string &exe = a.exe, &bios = a.bios, &disc = a.disc, &screenshot = a.screenshot, &vram_png = a.vram_png,
                    &wav = a.wav, &input_path = a.input_path;
  const bool expect_exit = a.expect_exit, quiet = a.quiet, realtime = a.realtime;

  unsigned long long frames = 3600, cycles = 0;
  if (!parse_count(a.frames_text, frames)) return usage_error(app, "--frames needs a whole number");
  if (!a.cycles_text.empty() && (!parse_count(a.cycles_text, cycles) || cycles == 0))
    return usage_error(app, "--cycles needs a positive whole number");
  psx::Console::PadType pads[2];
  for (int i = 0; i < 2; ++i)
    if (!parse_pad(a.pad_text[i], pads[i])) return usage_error(app, "--pad" + std::to_string(i + 1) + " needs " + kRunNeeds.at("--pad1"));
  std::vector<ScreenshotAt> shots;
  for (const auto& [frame, path] : a.shot_args) {
    ScreenshotAt shot{0, path};
    if (!parse_count(frame, shot.frame)) return usage_error(app, "--screenshot-at needs a frame number and a file");
    shots.push_back(shot);
  }
  auto usage = [&](const std::string& msg) { return usage_error(app, msg); };
  if (a.cpu != "interpreter" && a.cpu != "recompiler")
    return usage("--cpu must be interpreter or recompiler, not '" + a.cpu + "'");
  if (std::string why = a.render.check(); !why.empty()) return usage(why);
  if (exe.empty() && disc.empty() && bios.empty())
    return usage("--exe is required (or --disc to boot a disc, or --bios to start the BIOS alone)");
  const bool scripted = !input_path.empty() || !shots.empty() || realtime;
  if (scripted && cycles) return usage("--input, --screenshot-at and --realtime count frames: use --frames, not --cycles");
  for (const ScreenshotAt& shot : shots)
    if (shot.frame >= frames)
      return usage("--screenshot-at " + std::to_string(shot.frame) + " is never reached: --frames " +
                   std::to_string(frames) + " runs frames 0 to " + std::to_string(frames - 1));
  std::vector<InputPress> presses;

  psx::Console console;
  if (std::string error; !a.render.apply(console, 1, error)) {
    std::fprintf(stderr, "psxrl run: %s\n", error.c_str());
    return kBadInput;
  }
  console.set_idle_skip(!a.no_idle_skip);
  if (a.cpu == "recompiler") console.set_cpu_mode(psx::Console::CpuMode::Recompiler);
  console.on_tty = [](char c) { std::fputc(c, stdout); };
  console.on_log = [quiet](const std::string& m) {
    if (!quiet) std::fprintf(stderr, "psxrl: %s\n", m.c_str());
  };
  try {
    if (!input_path.empty()) presses = read_input_script(input_path);
    if (!bios.empty()) console.load_bios(bios);
    if (!disc.empty()) console.insert_disc(disc);
    // With a BIOS and no EXE, boot_disc() and boot_bios() both start the BIOS from reset and
    // nothing is side-loaded: the BIOS reads the disc itself, or shows its shell.
    if (!exe.empty()) console.boot_exe(exe);
    else if (!disc.empty()) console.boot_disc();
    else console.boot_bios();
    for (int port = 1; port <= 2; ++port) {
      console.plug_pad(port, pads[port - 1]);
      if (!a.memcards[port - 1].empty()) console.insert_memory_card(port, a.memcards[port - 1]);
    }
  } catch (const psx::InputError& e) {
    std::fprintf(stderr, "psxrl run: %s\n", e.what());
    return kBadInput;
  }

  // Headless: nothing looks at a frame as it ends (a screenshot converts VRAM as it is then, with
  // the drawing owed made first) and only --wav listens. Either way the same bits.
  console.set_pixels_observed(false);
  console.set_sound_observed(!wav.empty());
  if (!wav.empty()) console.keep_all_audio();
  Pacer pacer(60000.0 / 1001.0);  // NTSC frame rate
  std::vector<std::string> written;
  try {
    if (cycles) console.run_cycles(cycles);
    else if (!scripted) console.run_frames(frames);
    else run_scripted(console, frames, presses, shots, realtime ? &pacer : nullptr, written);
    std::fflush(stdout);
    if (!screenshot.empty()) {
      console.save_screenshot(screenshot);
      written.push_back(screenshot);
    }
    if (!vram_png.empty()) {
      console.save_vram_png(vram_png);
      written.push_back(vram_png);
    }
    if (!wav.empty()) {
      std::vector<psx::StereoSample> audio;
      console.take_audio(audio);
      psx::Console::save_wav(wav, audio);
      written.push_back(wav);
    }
  } catch (const psx::InputError& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "psxrl run: %s\n", e.what());
    return kBadInput;
  }
  if (!quiet) print_run_summary(stderr, console, exe, written);

  if (!console.fatal_error().empty()) {
    std::fprintf(stderr, "psxrl run: %s\n", console.fatal_error().c_str());
    return kProgramFailed;
  }
  if (auto code = console.exit_code()) {
    if (!quiet) std::fprintf(stderr, "psxrl run: program exited with code %u\n", *code);
    return *code > 255 ? 255 : static_cast<int>(*code);
  }
  if (expect_exit) {
    std::fprintf(stderr, "psxrl run: timed out after %llu cycles without the program exiting\n",
                 static_cast<unsigned long long>(console.cycles()));
    return kProgramFailed;
  }
  return kSuccess;
}

}  // namespace psxrl::cli
