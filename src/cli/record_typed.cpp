// Typed play for `psxrl record --stdin` (see record_typed.h).
#include "cli/record_typed.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "rl/agents/start_position.h"
#include "rl/level_map.h"

namespace psxrl::cli {

namespace {

const char* kFacing[] = {"north", "east", "south", "west"};

// The level's map with the ball as '@'; an item on a tile the ball has landed on is drawn as
// floor, since landing on it collects it (Tumble's rule). The map is the level's file, so
// anything else the game changes (a crumbled tile) is only in the picture.
class LevelText {
 public:
  explicit LevelText(rl::Env& env) : env_(env) {
    const rl::Integration& g = env.game();
    if (g.map_pattern.empty() || g.position_x.empty()) return;
    map_ = rl::read_level_map(rl::expand(g.map_pattern, env.level(), g, env.config().files));
    taken_.assign(map_.tiles.size(), false);
  }

  void print(int move, const std::string& what) {
    const rl::Integration& g = env_.game();
    std::string score = g.score_variable.empty() ? "" : ", score " + std::to_string(env_.raw(g.variable(g.score_variable)));
    std::printf("move %d%s%s\n", move, what.empty() ? "" : (": " + what).c_str(), score.c_str());
    if (map_.tiles.empty()) return;
    int x = static_cast<int>(env_.raw(g.variable(g.position_x)));
    int y = static_cast<int>(env_.raw(g.variable(g.position_y)));
    int facing = g.position_facing.empty() ? 0 : static_cast<int>(env_.raw(g.variable(g.position_facing)));
    if (x >= 0 && y >= 0 && x < map_.width && y < map_.height) taken_[static_cast<size_t>(y * map_.width + x)] = true;
    std::printf("ball at column %d, row %d, facing %s\n", x, y, kFacing[facing & 3]);
    for (int row = 0; row < map_.height; ++row) {
      std::string line;
      for (int col = 0; col < map_.width; ++col) {
        char c = static_cast<char>(map_.at(col, row));
        bool item = c == 'c' || c == 'f' || c == 'k';
        if (item && taken_[static_cast<size_t>(row * map_.width + col)]) c = '#';
        line += col == x && row == y ? '@' : c;
      }
      std::printf("  %s\n", line.c_str());
    }
  }

 private:
  rl::Env& env_;
  rl::LevelMap map_;
  std::vector<bool> taken_;
};

void save_picture(rl::Env& env, const std::string& dir, int move) {
  if (dir.empty()) return;
  char name[32];
  std::snprintf(name, sizeof name, "move%04d.png", move);
  std::string path = (std::filesystem::path(dir) / name).string();
  env.console().save_screenshot(path);
  std::printf("picture: %s\n", path.c_str());
}

std::string action_list(const std::vector<rl::Action>& actions) {
  std::string s;
  for (size_t i = 0; i < actions.size(); ++i) s += (i ? ", " : "") + actions[i].name + " (" + std::to_string(i) + ")";
  return s;
}

// The moves of a typed line ("FORWARD", "lookright,0"), or none if any word is not an action.
std::vector<int> parse_moves(const std::string& line, const std::vector<rl::Action>& actions) {
  try {
    return agents::parse_start_position(line, actions).moves;  // the same words as --start takes
  } catch (const std::invalid_argument&) {
    return {};
  }
}

}  // namespace

void record_typed_moves(rl::Env& env, memsearch::Recorder& rec, const std::string& frames_dir, std::istream& in) {
  if (env.game().mode != rl::Integration::StepMode::Moves)
    throw std::invalid_argument("game '" + env.game().name + "' steps by frames, not moves: --stdin records moves");
  // Env::step presses an action's buttons for its first `hold` frames (Console::press_for); the
  // session records what the pad held in each frame the move ran.
  const rl::Action* pressed = nullptr;
  std::uint32_t frame_of_move = 0;
  env.on_frame = [&](std::span<const psx::StereoSample>) {
    rec.frame_ran(frame_of_move++ < pressed->hold ? pressed->buttons : psx::u16{0}, 0);
  };
  LevelText text(env);
  std::printf("type moves, one or more a line (comma separated), 'quit' to stop; the actions: %s\n",
              action_list(env.actions()).c_str());
  std::printf("the level's map: @ the ball, S start, E exit, k key, c coin, f fruit, ^ spikes, %% crumbling, . void\n");
  text.print(0, "the level's start");
  save_picture(env, frames_dir, 0);
  std::fflush(stdout);
  int moves = 0;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (line == "quit") break;
    std::vector<int> typed = parse_moves(line, env.actions());
    if (typed.empty()) {  // a typing error: say so and read the next line
      std::printf("line %d: '%s' is not a move; the actions are %s\n", line_number, line.c_str(),
                  action_list(env.actions()).c_str());
      std::fflush(stdout);
      continue;
    }
    for (int action : typed) {
      pressed = &env.actions()[static_cast<size_t>(action)];
      frame_of_move = 0;
      const std::uint64_t before = rec.frames();
      rl::StepResult r = env.step(action);
      if (rec.frames() - before != r.info.game_frames)
        throw std::runtime_error("game '" + env.game().name + "': its script ran frames a session cannot record");
      char what[96];
      std::snprintf(what, sizeof what, "%s, reward %.4g", pressed->name.c_str(), r.reward);
      text.print(++moves, what);
      save_picture(env, frames_dir, moves);
      if (r.terminated || r.truncated) {
        std::printf("episode over: %s after %d moves, score %lld\n",
                    r.terminated ? r.info.outcome.c_str() : "truncated", moves, static_cast<long long>(r.info.score));
        std::fflush(stdout);
        env.on_frame = nullptr;
        return;
      }
      std::fflush(stdout);
    }
  }
  env.on_frame = nullptr;
}

}  // namespace psxrl::cli
