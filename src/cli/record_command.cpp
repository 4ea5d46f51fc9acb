// `psxrl record`: records a play session for `psxrl memsearch`: every frame's pad input, RAM
// snapshots at an interval and at marks, and the start state, into a session folder. A person
// plays in psxrl play's window and sets marks with F1..F4; headless, the input comes from an
// input script and the marks from a marks file.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli.h"
#include "cli/game_options.h"
#include "cli/input_script.h"
#include "cli/options.h"
#include "cli/play_view.h"
#include "cli/record_typed.h"
#include "core/console.h"
#include "core/input_error.h"
#include "memsearch/marks.h"
#include "memsearch/recorder.h"
#include "rl/env.h"

namespace psxrl::cli {

namespace {

const char* kRecordFooter =
    "Give either --game (booted as its integration boots it, to its ready point or a --level's\n"
    "start) or a program: --exe, --disc and/or --bios as psxrl run takes them.\n"
    "Without --input and --marks you play in a window (psxrl play's controls); F1 to F4 set marks labelled by\n"
    "--mark-labels; Escape or closing the window ends the recording, which is then written.\n"
    "With --stdin (and --game) you play without a window: type one move a line (the game's actions);\n"
    "after each, the picture goes to --frames-dir and a text view of the level is printed; the\n"
    "episode's end, 'quit' or the end of the input ends the recording (docs/offline.md).\n"
    "\n"
    "exit codes:\n"
    "  0  the session was written\n"
    "  1  usage error\n"
    "  2  bad input file (program, BIOS, disc, script, marks), unknown game or level, unwritable\n"
    "     output folder\n"
    "  3  the program failed while recording\n";

struct RecordArgs {
  std::string game, exe, disc, out, input, marks, mark_labels = "score,died,level_start,event", frames_dir;
  bool typed = false;
  rl::UserFiles files;
  int level = 0;
  unsigned long long frames = 0;
  unsigned interval = 60;

  void add_to(CLI::App& app) {
    app.add_option("--game", game, "record a game through its integration (games/NAME)")->type_name("NAME");
    app.add_option("--level", level, "with --game: start recording at this level's start")->type_name("N")->check(CLI::Range(1, 999));
    app.add_option("--exe", exe, "PS-X EXE to boot (as psxrl run --exe)")->type_name("FILE");
    add_user_file_options(app, files);
    app.add_option("--out", out, "session folder to write (created; an existing session is replaced)")
        ->type_name("DIR")
        ->transform(folder_path())
        ->required();
    app.add_option("--input", input, "input script for port 1, as psxrl run --input takes it")->type_name("FILE");
    app.add_option("--marks", marks, "marks file: one 'FRAME LABEL' per line, set when frame FRAME ends")
        ->type_name("FILE");
    app.add_option("--frames", frames,
                   "frames to record (default: the script's last press plus 120; in the window, until you quit)")
        ->type_name("N");
    app.add_option("--mark-labels", mark_labels, "labels of the marks F1..F4 set in the window (default\n"
                                                 "score,died,level_start,event)")
        ->type_name("L1,L2,L3,L4");
    app.add_option("--interval", interval, "frames between RAM snapshots (default 60; 0: marks and the end only)")
        ->type_name("N");
    app.add_flag("--stdin", typed, "with --game: play by typing moves on standard input, no window needed (from\n"
                                   "--level's start, default 1)");
    app.add_option("--frames-dir", frames_dir, "with --stdin: the picture at the start and after every move as PNG")
        ->type_name("DIR")
        ->transform(folder_path());
  }
};

// Buttons held on port 1 in each frame, as psxrl run's press_for would hold them.
std::vector<psx::u16> script_buttons(const std::vector<InputPress>& presses, unsigned long long frames) {
  std::vector<psx::u16> held(frames, 0);
  for (const InputPress& p : presses)
    for (unsigned long long f = p.frame; f < p.frame + p.hold && f < frames; ++f) held[f] |= p.buttons;
  return held;
}

// Boots what the arguments name; for --game the environment owns the console.
struct Booted {
  std::unique_ptr<rl::Env> env;
  std::unique_ptr<psx::Console> console;
  memsearch::SessionSource source;
  psx::Console& get() { return env ? env->console() : *console; }
};

std::string absolute(const std::string& p) { return p.empty() ? p : std::filesystem::absolute(p).string(); }

Booted boot(const RecordArgs& a) {
  Booted b;
  if (!a.game.empty()) {
    rl::EnvConfig config;
    config.game = a.game;
    config.files = a.files;
    config.obs = "ram";                // observations are not recorded: no level maps are needed
    config.starts_levels = a.level > 0;
    b.env = std::make_unique<rl::Env>(config);
    const rl::Integration& g = b.env->game();
    b.source = {absolute(g.exe), absolute(g.user_disc ? a.files.disc : g.disc), absolute(g.needs_bios ? a.files.bios : ""),
                g.name};
    if (a.level) b.env->reset(a.level, 0);
    return b;
  }
  b.source = {absolute(a.exe), absolute(a.files.disc), absolute(a.files.bios), ""};
  b.console = std::make_unique<psx::Console>();
  memsearch::boot_source(*b.console, b.source);
  return b;
}

std::vector<std::string> split_labels(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : text + ",") {
    if (c != ',') {
      cur += c;
      continue;
    }
    out.push_back(cur);
    cur.clear();
  }
  return out;
}

// A person plays in the window; F1..F4 set marks. Ends at --frames or when the player quits.
void record_in_window(psx::Console& console, memsearch::Recorder& rec, const RecordArgs& a,
                      const std::vector<std::string>& labels) {
  ViewOptions vo;
  vo.title = "psxrl: record " + (a.game.empty() ? std::filesystem::path(a.exe.empty() ? a.files.disc : a.exe).filename().string() : a.game);
  vo.max_frames = a.frames;
  PlayView view(vo, console);
  frontend::WindowInput in;
  std::vector<psx::StereoSample> audio;
  while (!view.stopped() && !console.stopped()) {
    rec.run_frame(in.buttons, 0);
    audio.clear();
    console.take_audio(audio);
    in = view.frame(audio);
    if (in.mark) {
      rec.mark(labels[static_cast<size_t>(in.mark - 1)]);
      std::printf("mark '%s' at frame %llu\n", labels[static_cast<size_t>(in.mark - 1)].c_str(),
                  static_cast<unsigned long long>(rec.frames() - 1));
      std::fflush(stdout);
    }
  }
}

}  // namespace

int record_command(const std::vector<std::string>& args) {
  CLI::App app{"Records a play session (inputs, RAM snapshots at an interval and at marks) for\n"
               "psxrl memsearch. Headless: input from --input, marks from --marks.",
               "psxrl record"};
  setup_app(app, kRecordFooter);
  RecordArgs a;
  a.add_to(app);
  if (auto code = parse_args(app, args, {{"--out", "a folder"}, {"--input", "a file"}, {"--marks", "a file"}}))
    return *code;
  if (a.game.empty() == (a.exe.empty() && a.files.disc.empty() && a.files.bios.empty()))
    return usage_error(app, "give either --game or a program (--exe, --disc or --bios)");
  if (a.level && a.game.empty()) return usage_error(app, "--level needs --game");
  if (a.typed && (a.game.empty() || !a.input.empty() || !a.marks.empty() || a.frames))
    return usage_error(app, "--stdin plays a --game's moves; it takes no --input, --marks or --frames");
  if (!a.frames_dir.empty() && !a.typed) return usage_error(app, "--frames-dir needs --stdin");
  if (a.typed && !a.level) a.level = 1;
  std::vector<std::string> labels = split_labels(a.mark_labels);
  if (labels.size() != 4) return usage_error(app, "--mark-labels needs four labels separated by commas");
  for (const std::string& l : labels) {
    try {
      memsearch::parse_marks("0 " + l + "\n", "--mark-labels");
    } catch (const psx::InputError& e) {
      return usage_error(app, std::string("--mark-labels: ") + e.what());
    }
  }
  const bool window = a.input.empty() && a.marks.empty() && !a.typed;
  std::string no_display = window ? frontend::display_problem() : "";
  if (!no_display.empty()) {
    std::fprintf(stderr, "psxrl record: recording by hand needs a window: %s (record headless with --input)\n",
                 no_display.c_str());
    return kBadInput;
  }

  try {
    std::vector<InputPress> presses = a.input.empty() ? std::vector<InputPress>{} : read_input_script(a.input);
    std::vector<memsearch::Mark> marks = a.marks.empty() ? std::vector<memsearch::Mark>{} : memsearch::read_marks(a.marks);
    unsigned long long frames = a.frames;
    if (!frames && !window) frames = (presses.empty() ? 0 : presses.back().frame + presses.back().hold) + 120;
    if (!marks.empty() && marks.back().frame >= frames)
      return usage_error(app, "mark at frame " + std::to_string(marks.back().frame) + " is past the last frame (" +
                                  std::to_string(frames - 1) + "): raise --frames");
    Booted booted = boot(a);
    psx::Console& console = booted.get();
    memsearch::Recorder rec(console, booted.source, a.interval);
    if (a.typed) {
      if (!a.frames_dir.empty()) std::filesystem::create_directories(a.frames_dir);
      record_typed_moves(*booted.env, rec, a.frames_dir, std::cin);
    } else if (window) {
      record_in_window(console, rec, a, labels);
    } else {
      std::vector<psx::u16> held = script_buttons(presses, frames);
      size_t next_mark = 0;
      for (unsigned long long f = 0; f < frames && !console.stopped(); ++f) {
        rec.run_frame(held[f], 0);
        for (; next_mark < marks.size() && marks[next_mark].frame == f; ++next_mark) rec.mark(marks[next_mark].label);
      }
    }
    if (rec.frames() == 0) {
      std::fprintf(stderr, "psxrl record: no frame was recorded: nothing written\n");
      return kBadInput;
    }
    if (!console.fatal_error().empty()) {
      std::fprintf(stderr, "psxrl record: %s\n", console.fatal_error().c_str());
      return kProgramFailed;
    }
    memsearch::Session s = rec.finish();
    memsearch::write_session(s, a.out);
    std::printf("recorded %llu frames, %zu snapshots, %zu marks into %s\n", static_cast<unsigned long long>(s.frames),
                s.snapshots.size(), s.marks.size(), a.out.c_str());
  } catch (const psx::InputError& e) {
    std::fprintf(stderr, "psxrl record: %s\n", e.what());
    return kBadInput;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "psxrl record: %s\n", e.what());
    return kBadInput;
  } catch (const std::invalid_argument& e) {  // --stdin for a game that steps by frames
    std::fprintf(stderr, "psxrl record: %s\n", e.what());
    return kBadInput;
  }
  return kSuccess;
}

}  // namespace psxrl::cli
