// Shared pieces of `psxrl play`: its options, and the two ways to play a level (a saved policy
// in play_command.cpp, a person in play_human.cpp), both through a PlayView.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "cli/play_view.h"
#include "cli/renderer_option.h"
#include "rl/agents/start_position.h"
#include "rl/env.h"

namespace psxrl::cli {

struct PlayOptions {
  std::string game, obs, policy, frames_dir, rollout;
  // Where each episode starts (seed 4.2.6, rl/agents/start_position.h): --start's walk, else the
  // policy's training start, else the level's own.
  std::optional<std::string> start;
  std::string cpu = "recompiler";
  int level = 1;
  std::uint64_t episodes = 1, seed = 0;
  std::optional<std::uint32_t> max_moves;
  bool headless = false;
  ViewOptions view;
  RendererArgs render;  // --renderer; with gl, --scale (view.scale) is the drawing scale
};

// Prints one episode's line: "episode N: score S, OUTCOME, M moves, F frames" (human play has
// no moves and leaves them out).
void print_episode(std::uint64_t episode, std::int64_t score, const std::string& outcome,
                   std::optional<std::uint32_t> moves, std::uint64_t frames);

// A person plays `p.level` of `env` in the view's window, each episode from `start`. Returns the
// exit code.
int play_human(rl::Env& env, const PlayOptions& p, const agents::StartPosition& start, PlayView& view);

}  // namespace psxrl::cli
