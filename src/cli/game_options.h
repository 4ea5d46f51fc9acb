// Options that `train` and `play` share: which game and the user's files it may need (Kula World:
// disc, BIOS, level states and maps), the CPU core, and the mapping of errors to exit codes.
#pragma once
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "cli/options.h"
#include "rl/env.h"

namespace psxrl::cli {

inline void add_user_file_options(CLI::App& app, rl::UserFiles& files) {
  app.add_option("--disc", files.disc, "your disc image, for games that need one (Kula World)")->type_name("FILE");
  app.add_option("--bios", files.bios, "your PlayStation BIOS image, for games that need one")->type_name("FILE");
  app.add_option("--states", files.states_dir, "folder of level-start save states (Kula World)")
      ->type_name("DIR")
      ->transform(folder_path());
  app.add_option("--maps", files.maps_dir, "folder of level maps (Kula World)")->type_name("DIR")->transform(folder_path());
}

// --cpu: the environments' CPU core. Only speed differs (the cores compute the same bits), so a
// run's config and checkpoints do not record it.
inline void add_cpu_option(CLI::App& app, std::string& cpu) {
  app.add_option("--cpu", cpu, "CPU core: recompiler (default, faster) or interpreter (the reference); same results")
      ->type_name("CORE")
      ->check(CLI::IsMember({"recompiler", "interpreter"}));
}

inline const char* kAgentExitCodes =
    "exit codes:\n"
    "  0  success\n"
    "  1  usage error\n"
    "  2  unknown game, level, agent or observation; bad or mismatched checkpoint or policy;\n"
    "     missing or bad game files; unwritable output folder\n"
    "  3  the game failed while running\n";

}  // namespace psxrl::cli
