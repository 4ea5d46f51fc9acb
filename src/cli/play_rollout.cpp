// The JSON Lines file of `psxrl play --rollout` (see play_rollout.h).
#include "cli/play_rollout.h"

#include <stdexcept>

#include "rl/agents/checkpoint.h"

namespace psxrl::cli {

namespace {

std::string list_of(const std::vector<int>& v) {
  std::string s;
  for (int x : v) s += (s.empty() ? "" : ",") + std::to_string(x);
  return "[" + s + "]";
}

}  // namespace

RolloutWriter::RolloutWriter(const std::string& path) : path_(path) {
  if (path.empty()) return;
  out_.open(path, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(path + ": cannot write the rollout file");
}

void RolloutWriter::begin(std::uint64_t episode, int level, std::uint64_t seed, const std::vector<int>& start) {
  head_ = "{\"episode\":" + std::to_string(episode) + ",\"level\":" + std::to_string(level) +
          ",\"seed\":" + std::to_string(seed) + ",\"start\":" + list_of(start);
  actions_.clear();
  rewards_.clear();
}

void RolloutWriter::move(int action, double reward) {
  actions_ += (actions_.empty() ? "" : ",") + std::to_string(action);
  rewards_ += (rewards_.empty() ? "" : ",") + agents::format_double(reward);
}

void RolloutWriter::end(const rl::StepResult& last, const std::string& outcome) {
  if (path_.empty()) return;
  // Outcomes are the integration's words (win, lose) or play's (truncated, stopped): no escaping.
  out_ << head_ << ",\"actions\":[" << actions_ << "],\"rewards\":[" << rewards_
       << "],\"terminated\":" << (last.terminated ? "true" : "false")
       << ",\"truncated\":" << (last.truncated ? "true" : "false") << ",\"score\":" << last.info.score
       << ",\"outcome\":\"" << outcome << "\",\"moves\":" << last.info.moves
       << ",\"episode_reward\":" << agents::format_double(last.info.episode_reward) << "}\n";
  out_.flush();
  if (!out_) throw std::runtime_error(path_ + ": cannot write the rollout file");
}

}  // namespace psxrl::cli
