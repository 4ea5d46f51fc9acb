// A game integration: everything one game needs to become an environment, read from
// `games/<name>/game.toml` (declarative data) plus an optional Lua script for what data cannot
// say (docs/integrating-a-game.md). Nothing game-specific lives in C++: this is the whole
// vocabulary an integration can use. Every defect is a psx::InputError naming the manifest,
// the line and the field.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/types.h"

namespace psxrl::rl {

struct Variable {
  enum class Type { U8, S8, U16, S16, U32, S32 };
  std::string name;
  psx::u32 address = 0;  // KSEG0/KUSEG/KSEG1 RAM address (any mirror)
  Type type = Type::U32;
  double scale = 1.0;    // value() = raw * scale
  unsigned width() const { return type == Type::U8 || type == Type::S8 ? 1 : type == Type::U16 || type == Type::S16 ? 2 : 4; }
};

struct Action {
  std::string name;
  psx::u16 buttons = 0;  // pad_button bits on port 1
  psx::u32 hold = 1;     // frames the buttons stay down
};

// "variable is one of values": boot and level readiness.
struct Condition {
  std::string variable;
  std::vector<std::int64_t> values;
};

inline bool contains_string(const std::vector<std::string>& values, const std::string& x) {
  for (const auto& v : values)
    if (v == x) return true;
  return false;
}

inline bool contains_value(const std::vector<std::int64_t>& values, std::int64_t x) {
  for (auto v : values)
    if (v == x) return true;
  return false;
}

struct Integration {
  std::string name, title;
  std::string folder;    // the integration's folder
  std::string manifest;  // its game.toml
  std::string script;    // Lua file, empty when none
  std::uint32_t script_memory_mib = 32;  // the most the Lua state may hold (lua/lua_host.h)

  // Boot: a built-in EXE or disc (paths resolved), or a user's disc (+ BIOS).
  std::string exe, disc;
  bool user_disc = false, needs_bios = false;
  std::string bios;  // a BIOS file the manifest names (resolved); --bios overrides it
  // Set when the built-in exe/disc is in none of the folders searched: "game.toml:N: [boot] exe:
  // ..." naming them. Booting reports it; parsing alone (tools, fuzzing) does not need the file.
  std::string missing_program;
  std::vector<std::string> disc_sha1;  // accepted SHA-1s of the data track; empty accepts any
  Condition boot_ready;
  psx::u32 boot_max_frames = 600;

  std::vector<Variable> variables;
  std::vector<Action> actions;

  // Levels: how level N starts.
  enum class LevelStart { Request, State, Script };
  int level_count = 1;
  LevelStart level_start = LevelStart::Request;
  std::string request_variable;
  std::string state_pattern;  // with placeholders, see expand()
  std::string map_pattern;    // empty: no maps (no simple/local observations)
  Condition level_ready;
  psx::u32 level_max_frames = 600;

  // Moves: the seed's delimiter (§3.2.4) or ALE-style frame stepping.
  enum class StepMode { Moves, Frames };
  StepMode mode = StepMode::Moves;
  std::vector<std::string> watch;  // variables whose change means a move is still running
  bool watch_audio = true;
  psx::u32 audio_threshold = 64;   // peak sample magnitude counted as sound
  psx::u32 initial_delay = 6, delay = 4, max_move_frames = 600;
  psx::u32 frame_skip_min = 4, frame_skip_max = 4;
  double sticky = 0.0;

  // Episode: outcome from a state variable, time left, caps.
  std::string state_variable;
  std::vector<std::int64_t> win_states, lose_states;
  std::string time_variable;
  psx::u32 max_moves = 1000;
  psx::u64 max_frames = 0;  // 0: none

  // Position for simple/local observations: variables, or the script's position().
  std::string position_x, position_y, position_facing;

  // Reward table in units of (1 - gamma): score increases, winning, losing (seed Table 3.3).
  std::string score_variable;
  std::vector<std::pair<std::int64_t, double>> item_rewards;  // largest score first
  double win_reward = 1.0, lose_reward = -1.0;

  // Observation geometry.
  int visual_x = 0, visual_y = 0, visual_w = 320, visual_h = 240;
  int visual_out_w = 80, visual_out_h = 60;
  int local_ahead = 2, local_behind = 0, local_side = 1;
  int audio_frames = 64;

  const Variable* find_variable(const std::string& name) const;
  const Variable& variable(const std::string& name) const;  // must exist (checked at load)
};

// User-supplied files an integration may need (Kula World: disc, BIOS, level states and maps).
struct UserFiles {
  std::string disc, bios, states_dir, maps_dir;
};

// Reads `<games_dir>/<name>/game.toml`; `build_games_dir` is where built-in programs are found
// when they are not in the integration's folder.
Integration load_integration(const std::string& games_dir, const std::string& name,
                             const std::string& build_games_dir);
// Parses manifest text (`file` names it in errors; `folder` resolves relative paths). A non-empty
// `folder_name` must equal the manifest's `name` (a game is chosen by its folder's name).
Integration parse_integration(const std::string& text, const std::string& file, const std::string& folder,
                              const std::string& build_games_dir, const std::string& folder_name = "");

// What the user must supply and has not, one line each ("your PlayStation BIOS image: pass --bios
// FILE"), so that one message names every missing file: the BIOS and disc the boot needs, the
// level states a state start needs when `needs_states`, and the maps when `needs_maps` (a
// simple/local observation).
std::vector<std::string> missing_user_files(const Integration& g, const UserFiles& files, bool needs_states,
                                            bool needs_maps);
// One message naming them all, with where to read about them (help_page()).
std::string missing_files_message(const Integration& g, const std::vector<std::string>& missing);
// The integration's README.md when it has one, else the integration guide's section on user files.
std::string help_page(const Integration& g);

// Expands {level}, {level:02}, {states}, {maps} and {folder} in a path pattern; a pattern not
// starting with a placeholder is relative to the integration's folder.
std::string expand(const std::string& pattern, int level, const Integration& game, const UserFiles& files);

// Names of the integrations in a games folder (sub-folders holding a game.toml), sorted.
std::vector<std::string> list_integrations(const std::string& games_dir);

}  // namespace psxrl::rl
