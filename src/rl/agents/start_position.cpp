// Start positions as walks from the level's start (see start_position.h).
#include "rl/agents/start_position.h"

#include <cctype>
#include <sstream>
#include <stdexcept>

namespace psxrl::agents {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

int action_index(const std::string& word, const std::vector<rl::Action>& actions) {
  for (size_t i = 0; i < actions.size(); ++i)
    if (upper(actions[i].name) == upper(word) || std::to_string(i) == word) return static_cast<int>(i);
  std::string names;
  for (size_t i = 0; i < actions.size(); ++i) names += (i ? ", " : "") + actions[i].name + " (" + std::to_string(i) + ")";
  throw std::invalid_argument("start position '" + word + "' is not an action; the actions are " + names);
}

}  // namespace

StartPosition parse_start_position(const std::string& text, const std::vector<rl::Action>& actions) {
  StartPosition p{text, {}};
  if (text.empty()) return p;
  std::istringstream in(text);
  for (std::string word; std::getline(in, word, ',');) p.moves.push_back(action_index(word, actions));
  if (text.back() == ',') throw std::invalid_argument("start position '" + text + "' ends with a comma");
  return p;
}

const rl::Observation& begin_at(rl::Env& env, int level, const StartPosition& start, std::uint64_t seed,
                                rl::StepInfo* info) {
  rl::StepInfo first;
  const rl::Observation& at_level_start = env.reset(level, seed, &first);
  if (start.moves.empty()) {
    if (info) *info = first;
    return at_level_start;
  }
  std::uint64_t frames = first.game_frames;
  for (size_t i = 0; i < start.moves.size(); ++i) {
    rl::StepResult r = env.step(start.moves[i]);
    frames += r.info.game_frames;
    std::string what = r.terminated ? "ends the episode (" + r.info.outcome + ")"
                       : r.info.score != 0 ? "scores " + std::to_string(r.info.score) + " points"
                                           : "";
    if (!what.empty())
      throw std::invalid_argument("start position '" + start.text + "': move " + std::to_string(i + 1) + " (" +
                                  env.actions()[static_cast<size_t>(start.moves[i])].name + ") " + what +
                                  " on level " + std::to_string(level) +
                                  "; a start position is a walk that collects nothing and ends nothing");
    // The walk is not the episode: a move or frame cap it reached restarts from where it is.
    if (r.truncated) env.reset_to(env.snapshot(), seed, nullptr);
  }
  const rl::Observation& obs = env.reset_to(env.snapshot(), seed, info);
  if (info) info->game_frames += frames;
  return obs;
}

}  // namespace psxrl::agents
