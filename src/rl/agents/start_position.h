// Start positions other than the level's own (seed §4.2.6): the seed made each one by moving the
// player "without picking up objects" to a place and saving the console state there. Here a
// start position is that walk, written as the game's actions: every episode from it starts the
// level (reset, so the episode's seed still seeds the game), plays the walk, and begins at the
// state the game is then in. A walk that scores, wins or loses is refused: the episode would not
// start from a clean level at another place. The episode's move and frame caps do not count the walk.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "rl/env.h"

namespace psxrl::agents {

struct StartPosition {
  std::string text;        // as given: action names or numbers, comma separated ("" = the level's start)
  std::vector<int> moves;  // the walk, as action indices
};

// Parses "NAME,NAME,..." (the integration's action names, any case, or their 0-based numbers);
// "" is the level's own start. Throws std::invalid_argument naming the word and the actions.
StartPosition parse_start_position(const std::string& text, const std::vector<rl::Action>& actions);

// Starts an episode of `level` at `start`: reset(level, seed), the walk, then an episode that
// begins there (moves, frames and reward from 0). `info->game_frames` counts every frame run, the
// walk's included. Throws std::invalid_argument when the walk scores or ends the episode.
const rl::Observation& begin_at(rl::Env& env, int level, const StartPosition& start, std::uint64_t seed,
                                rl::StepInfo* info);

}  // namespace psxrl::agents
