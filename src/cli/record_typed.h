// `psxrl record --game G --stdin`: a person plays without a display, one move per line typed on
// standard input (the integration's actions, by name or number). After every move the picture
// is written as PNG and a short text view of the level is printed, so the player can look and
// type the next move; the frames are recorded like any session, for memsearch and psxrl.offline.
#pragma once
#include <istream>
#include <string>

#include "memsearch/recorder.h"
#include "rl/env.h"

namespace psxrl::cli {

// Plays `env`'s level (already started) from the moves read from `in` until the episode ends, a
// line says "quit", or the input ends; every frame goes into `rec`. Writes moveNNNN.png into
// `frames_dir` unless it is "". Throws std::invalid_argument for a game whose steps are not
// delimited moves (a frame-skip step's buttons depend on the game's random sticky actions).
void record_typed_moves(rl::Env& env, memsearch::Recorder& rec, const std::string& frames_dir, std::istream& in);

}  // namespace psxrl::cli
