// Human play (`psxrl play` without --policy): the keyboard or a gamepad drives pad 1 frame by
// frame while the window shows the game; an episode ends at the integration's win or loss. F5
// saves the level-start state that integrations whose levels start from states load (Kula
// World's levelNN.state), so a player can make them.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "cli/cli.h"
#include "cli/play.h"
#include "core/console.h"
#include "rl/vec_env.h"

namespace psxrl::cli {

namespace {

bool starts_from_states(const rl::Env& env) { return env.game().level_start == rl::Integration::LevelStart::State; }

std::string level_state_path(const rl::Env& env, int level) {
  return rl::expand(env.game().state_pattern, level, env.game(), env.config().files);
}

// F5: the console as it is now becomes the level's start state, written atomically.
void save_level_state(rl::Env& env, int level) {
  const rl::Integration& g = env.game();
  if (!starts_from_states(env)) {
    std::printf("game '%s' starts its levels without save states: nothing to save\n", g.name.c_str());
    return;
  }
  std::string path = level_state_path(env, level);
  try {
    std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    env.console().save_state_file(path);
    std::printf("saved level %d's start state in %s\n", level, path.c_str());
  } catch (const std::exception& e) {  // an unwritable folder is reported; play goes on
    std::fprintf(stderr, "psxrl play: cannot save the level state: %s\n", e.what());
  }
  std::fflush(stdout);
}

std::int64_t score_now(const rl::Env& env) {
  const std::string& name = env.game().score_variable;
  return name.empty() ? 0 : env.raw(env.game().variable(name));
}

// Runs frames with the player's buttons until a win or loss (unless `judge` is false) or the
// view stops; returns the outcome ("" when the view stopped first) and counts the frames.
std::string play_frames(rl::Env& env, PlayView& view, bool judge, std::uint64_t& frames) {
  psx::Console& c = env.console();
  std::vector<psx::StereoSample> audio;
  frontend::WindowInput in;
  while (!view.stopped()) {
    c.set_buttons(1, in.buttons);
    c.run_frame();
    ++frames;
    if (!c.fatal_error().empty()) throw std::runtime_error("the console stopped: " + c.fatal_error());
    audio.clear();
    c.take_audio(audio);
    in = view.frame(audio);
    if (judge) {
      std::string out = env.outcome();
      if (!out.empty()) return out;
    }
  }
  return "";
}

}  // namespace

int play_human(rl::Env& env, const PlayOptions& p, const agents::StartPosition& start, PlayView& view) {
  // The Env's constructor has asked for a --states folder where the levels start from states.
  view.on_save = [&] { save_level_state(env, p.level); };
  for (std::uint64_t ep = 1; ep <= p.episodes && !view.stopped(); ++ep) {
    // A level whose start state is not made yet is played from the game's boot: the player goes
    // to the level and presses F5 at its start. Until then there is no level to judge.
    bool from_boot = starts_from_states(env) && !std::filesystem::exists(level_state_path(env, p.level));
    if (from_boot) {
      std::printf("level %d's start state %s does not exist yet: playing from the game's boot; press F5 at the "
                  "level's start to save it\n", p.level, level_state_path(env, p.level).c_str());
    } else {
      agents::begin_at(env, p.level, start, rl::episode_seed(p.seed, 0, ep - 1), nullptr);
    }
    std::fflush(stdout);
    std::uint64_t frames = 0;
    std::string out = play_frames(env, view, !from_boot, frames);
    print_episode(ep, score_now(env), out.empty() ? "stopped" : out, std::nullopt, frames);
    if (from_boot) break;
  }
  return kSuccess;
}

}  // namespace psxrl::cli
