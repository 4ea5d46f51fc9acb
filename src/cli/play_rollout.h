// `psxrl play --rollout FILE`: a policy's episodes as JSON Lines, one line per episode with its
// level, seed, start walk, every move's action and reward, and how it ended, so that
// psxrl.offline can replay them in a Python environment of any observation and export them as
// a Minari dataset (docs/offline.md).
#pragma once
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "rl/env.h"

namespace psxrl::cli {

class RolloutWriter {
 public:
  // Creates (or truncates) `path`; "" writes nothing. Throws std::runtime_error naming the file.
  explicit RolloutWriter(const std::string& path);

  void begin(std::uint64_t episode, int level, std::uint64_t seed, const std::vector<int>& start);
  void move(int action, double reward);
  // Writes the episode's line: `last` is its final step (unused when no move was made).
  void end(const rl::StepResult& last, const std::string& outcome);

 private:
  std::string path_;
  std::ofstream out_;
  std::string head_, actions_, rewards_;
};

}  // namespace psxrl::cli
