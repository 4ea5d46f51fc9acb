// `psxrl run`: boots a PS-X EXE (with a BIOS or the HLE kernel), a disc, or a BIOS alone headless,
// prints the program's TTY output, and exits with the program's exit code or when the frame/cycle
// limit is reached.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli.h"
#include "cli/input_script.h"
#include "cli/pacer.h"
#include "core/console.h"

namespace psxrl::cli {

namespace {

const char* kRunHelp =
    "usage: psxrl run --exe FILE | --disc FILE [--bios FILE] [--frames N | --cycles N] [--expect-exit] [--quiet]\n"
    "                 [--pad1 TYPE] [--pad2 TYPE] [--memcard1 FILE] [--memcard2 FILE]\n"
    "                 [--screenshot FILE] [--vram FILE] [--wav FILE]\n"
    "                 [--input FILE] [--screenshot-at FRAME FILE]... [--realtime]\n"
    "       psxrl run --bios FILE [the same options]   (the BIOS alone: no EXE, no disc)\n"
    "\n"
    "Runs a PlayStation program headless and prints what it writes to the TTY (debug port\n"
    "0x1F802080, DUART 0x1F802023, BIOS putchar).\n"
    "\n"
    "options:\n"
    "  --exe FILE       PS-X EXE to run\n"
    "  --disc FILE      disc image (.cue, .iso or a raw .bin) to insert; without --exe it is booted\n"
    "                   (with --bios by the BIOS itself from reset, as on the console)\n"
    "  --bios FILE      BIOS image (exactly 512 KiB); without it the HLE kernel is used; alone,\n"
    "                   the BIOS starts from reset with no disc (its shell)\n"
    "  --frames N       stop after N frames (default 3600)\n"
    "  --cycles N       stop after N CPU cycles (instead of --frames)\n"
    "  --expect-exit    reaching the limit is a failure (exit 3): the program must exit itself\n"
    "  --quiet          no summary or diagnostics on standard error\n"
    "  --realtime       run no faster than the console (59.94 frames per second), to watch\n"
    "  --pad1 TYPE      controller in port 1: digital (default), dualshock or none\n"
    "  --pad2 TYPE      controller in port 2: none (default), digital or dualshock\n"
    "  --memcard1 FILE  memory card in slot 1 (raw 128 KiB image; created on the first write)\n"
    "  --memcard2 FILE  memory card in slot 2\n"
    "  --screenshot FILE  write the displayed picture as PNG at the end of the run\n"
    "  --vram FILE      write all of VRAM (1024x512) as PNG at the end of the run\n"
    "  --wav FILE       write the whole run's audio (stereo 16-bit, 44.1 kHz) to FILE\n"
    "  --input FILE     press port 1's buttons from a script: one line per press,\n"
    "                   FRAME BUTTONS [HOLD_FRAMES], frames counted from 0, BUTTONS joined\n"
    "                   by '+' from up down left right cross circle square triangle l1 l2\n"
    "                   r1 r2 start select l3 r3, HOLD_FRAMES default 1, '#' comments\n"
    "  --screenshot-at FRAME FILE  write the displayed picture as PNG when frame FRAME\n"
    "                   (counted from 0) ends; repeatable; needs --frames above FRAME\n"
    "\n"
    "exit codes:\n"
    "  the program's own exit code (written to 0x1F802082; values above 255 exit as 255)\n"
    "  0  the limit was reached (without --expect-exit)\n"
    "  1  usage error\n"
    "  2  bad input file\n"
    "  3  the program failed (fatal guest error) or timed out under --expect-exit\n";

int usage(const std::string& msg) {
  std::fprintf(stderr, "psxrl run: %s\n\n%s", msg.c_str(), kRunHelp);
  return kUsage;
}

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
// each is due in and writing the screenshots due when a frame ends, paced to real time when a
// pacer is given. A screenshot that cannot be written throws InputError.
void run_scripted(psx::Console& console, unsigned long long frames, const std::vector<InputPress>& presses,
                  const std::vector<ScreenshotAt>& shots, Pacer* pacer) {
  size_t next_press = 0;
  for (unsigned long long f = 0; f < frames && !console.stopped(); ++f) {
    for (; next_press < presses.size() && presses[next_press].frame == f; ++next_press)
      console.press_for(1, presses[next_press].buttons, presses[next_press].hold);
    console.run_frame();
    if (pacer) pacer->wait_frame();
    for (const ScreenshotAt& shot : shots)
      if (shot.frame == f) console.save_screenshot(shot.path);
  }
}

}  // namespace

int run_command(const std::vector<std::string>& args) {
  std::string exe, bios, disc, screenshot, vram_png, wav;
  unsigned long long frames = 3600, cycles = 0;
  bool expect_exit = false, quiet = false, realtime = false;
  psx::Console::PadType pads[2] = {psx::Console::PadType::Digital, psx::Console::PadType::None};
  std::string memcards[2];
  std::string input_path;
  std::vector<ScreenshotAt> shots;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= args.size()) return false;
      out = args[++i];
      return true;
    };
    std::string v;
    if (a == "--help" || a == "-h") {
      std::fputs(kRunHelp, stdout);
      return kSuccess;
    } else if (a == "--exe") {
      if (!value(exe)) return usage("--exe needs a file");
    } else if (a == "--disc") {
      if (!value(disc)) return usage("--disc needs a file");
    } else if (a == "--bios") {
      if (!value(bios)) return usage("--bios needs a file");
    } else if (a == "--frames") {
      if (!value(v) || !parse_count(v, frames)) return usage("--frames needs a whole number");
    } else if (a == "--cycles") {
      if (!value(v) || !parse_count(v, cycles) || cycles == 0) return usage("--cycles needs a positive whole number");
    } else if (a == "--screenshot") {
      if (!value(screenshot)) return usage("--screenshot needs a file");
    } else if (a == "--vram") {
      if (!value(vram_png)) return usage("--vram needs a file");
    } else if (a == "--wav") {
      if (!value(wav)) return usage("--wav needs a file");
    } else if (a == "--input") {
      if (!value(input_path)) return usage("--input needs a file");
    } else if (a == "--screenshot-at") {
      ScreenshotAt shot;
      if (!value(v) || !parse_count(v, shot.frame) || !value(shot.path))
        return usage("--screenshot-at needs a frame number and a file");
      shots.push_back(shot);
    } else if (a == "--expect-exit") {
      expect_exit = true;
    } else if (a == "--quiet") {
      quiet = true;
    } else if (a == "--realtime") {
      realtime = true;
    } else if (a == "--pad1" || a == "--pad2") {
      if (!value(v) || !parse_pad(v, pads[a[5] - '1']))
        return usage(a + " needs digital, dualshock or none");
    } else if (a == "--memcard1" || a == "--memcard2") {
      if (!value(memcards[a[9] - '1'])) return usage(a + " needs a file");
    } else {
      return usage("unknown option '" + a + "'");
    }
  }
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
      if (!memcards[port - 1].empty()) console.insert_memory_card(port, memcards[port - 1]);
    }
  } catch (const psx::InputError& e) {
    std::fprintf(stderr, "psxrl run: %s\n", e.what());
    return kBadInput;
  }

  if (!wav.empty()) console.keep_all_audio();
  Pacer pacer(60000.0 / 1001.0);  // NTSC frame rate
  try {
    if (cycles) console.run_cycles(cycles);
    else if (!scripted) console.run_frames(frames);
    else run_scripted(console, frames, presses, shots, realtime ? &pacer : nullptr);
    std::fflush(stdout);
    if (!screenshot.empty()) console.save_screenshot(screenshot);
    if (!vram_png.empty()) console.save_vram_png(vram_png);
    if (!wav.empty()) {
      std::vector<psx::StereoSample> audio;
      console.take_audio(audio);
      psx::Console::save_wav(wav, audio);
    }
  } catch (const psx::InputError& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "psxrl run: %s\n", e.what());
    return kBadInput;
  }

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
