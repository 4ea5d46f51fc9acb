// The learning-curve image, like the seed's Fig. 4.6: score per episode as a moving average over
// 5 episodes, training episodes in red and greedy test episodes in blue, on a white canvas with a
// gray grid line every `grid` points and a vertical one every power-of-ten episodes. No text: the
// axes are episodes (x, from 0) and game score (y, from 0 or the lowest score).
#pragma once
#include <string>
#include <vector>

#include "rl/agents/trainer.h"

namespace psxrl::agents {

// Means of the last `window` values at each position (fewer at the start).
std::vector<double> moving_average(const std::vector<double>& values, size_t window);

// Throws std::runtime_error naming the file when it cannot be written.
void write_learning_curve(const std::string& path, const std::vector<EpisodeRecord>& records);

}  // namespace psxrl::agents
