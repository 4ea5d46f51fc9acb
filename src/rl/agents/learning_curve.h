// The learning-curve image, like the seed's Fig. 4.6: score per episode as a moving average over
// 5 episodes, training episodes in red and greedy test episodes in blue, on a white canvas with
// labelled axes (episodes along x from 0, game score up y from 0 or the lowest score), a gray grid
// at the labelled ticks and every 1000 points, and a legend.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "rl/agents/trainer.h"

namespace psxrl::agents {

// Means of the last `window` values at each position (fewer at the start).
std::vector<double> moving_average(const std::vector<double>& values, size_t window);

// Labelled episode ticks from 0 to `max_episode`: every power of ten below it (halved when that
// gives fewer than 3 steps).
std::vector<double> episode_ticks(double max_episode);
// Labelled score ticks in [lo, hi] (multiples of 1000): every 1, 2 or 5 (times a power of ten)
// thousand, whichever is the first to give at most 8 labels.
std::vector<double> score_ticks(double lo, double hi);
// Pixels a label takes across: 6 per character, less the last one's blank column.
int text_width(const std::string& text);

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // rows top to bottom, 3 bytes a pixel
};
RgbImage render_learning_curve(const std::vector<EpisodeRecord>& records);
// Throws std::runtime_error naming the file when it cannot be written.
void write_learning_curve(const std::string& path, const std::vector<EpisodeRecord>& records);

}  // namespace psxrl::agents
