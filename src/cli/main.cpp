// psxrl: the command-line front door. Dispatches to the subcommands.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/cli.h"

namespace {

const char* kHelp =
    "usage: psxrl <command> [options]\n"
    "\n"
    "commands:\n"
    "  run        run PlayStation software headless (see psxrl run --help)\n"
    "  train      train an agent on a game level (see psxrl train --help)\n"
    "  play       play a level in a window with sound, by a saved policy or by you; or headless;\n"
    "             prints each episode's score, records video (see psxrl play --help)\n"
    "  record     record a play session (inputs, RAM snapshots, marks) for memsearch\n"
    "  memsearch  find a game's variables in a recorded session's RAM (see docs/memsearch.md)\n"
    "  sweep      train a grid of configurations x seeds on Ray, in Python (see docs/scaling.md)\n"
    "  compat     run programs and discs under the HLE kernel (and a BIOS) and report what works,\n"
    "             with screenshots (see psxrl compat --help, docs/compat.md)\n"
    "  experiment run one of the seed's studies as a sweep (see docs/results.md)\n"
    "\n"
    "exit codes:\n"
    "  0  success\n"
    "  1  usage error\n"
    "  2  bad input file (disc, cue, EXE, BIOS, save state, memory card, manifest, script,\n"
    "     checkpoint or policy), unknown game, level, agent or observation, unwritable output\n"
    "  3  the emulated program failed or timed out\n"
    "  psxrl run also exits with the code a program writes to the debug port 0x1F802082\n";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kHelp, args.empty() ? stderr : stdout);
    return args.empty() ? psxrl::cli::kUsage : psxrl::cli::kSuccess;
  }
  std::string cmd = args[0];
  args.erase(args.begin());
  if (cmd == "run") return psxrl::cli::run_command(args);
  if (cmd == "train") return psxrl::cli::train_command(args);
  if (cmd == "play") return psxrl::cli::play_command(args);
  if (cmd == "record") return psxrl::cli::record_command(args);
  if (cmd == "memsearch") return psxrl::cli::memsearch_command(args);
  if (cmd == "sweep") return psxrl::cli::sweep_command(args);
  if (cmd == "compat") return psxrl::cli::compat_command(args);
  if (cmd == "experiment") return psxrl::cli::experiment_command(args);
  std::fprintf(stderr, "psxrl: unknown command '%s'\n\n%s", cmd.c_str(), kHelp);
  return psxrl::cli::kUsage;
}
