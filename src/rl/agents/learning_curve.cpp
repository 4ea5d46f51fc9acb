// Plotting the learning curve (see learning_curve.h) into an RGB canvas written with libpng.
#include "rl/agents/learning_curve.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "gpu/png_writer.h"

namespace psxrl::agents {

namespace {

constexpr int kWidth = 640, kHeight = 360, kMargin = 24;
constexpr size_t kWindow = 5;  // the seed's Fig. 4.6 averages over 5 episodes

struct Rgb {
  std::uint8_t r, g, b;
};

class Canvas {
 public:
  Canvas() : pixels_(static_cast<size_t>(kWidth) * kHeight * 3, 255) {}
  void set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) return;
    std::uint8_t* p = &pixels_[(static_cast<size_t>(y) * kWidth + x) * 3];
    p[0] = c.r, p[1] = c.g, p[2] = c.b;
  }
  // Bresenham's line, two pixels thick so a curve stays visible when the image is scaled down.
  void line(int x0, int y0, int x1, int y1, Rgb c) {
    int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0), sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, err = dx + dy;
    for (;;) {
      set(x0, y0, c);
      set(x0, y0 + 1, c);
      if (x0 == x1 && y0 == y1) return;
      int e2 = 2 * err;
      if (e2 >= dy) err += dy, x0 += sx;
      if (e2 <= dx) err += dx, y0 += sy;
    }
  }
  const std::uint8_t* data() const { return pixels_.data(); }

 private:
  std::vector<std::uint8_t> pixels_;
};

// Plot area mapping: episode 0..max_x to the left..right margin, score lo..hi bottom to top.
struct Axes {
  double max_x, lo, hi;
  int x(double episode) const { return kMargin + static_cast<int>(std::lround(episode / max_x * (kWidth - 2 * kMargin))); }
  int y(double score) const {
    return kHeight - kMargin - static_cast<int>(std::lround((score - lo) / (hi - lo) * (kHeight - 2 * kMargin)));
  }
};

void plot(Canvas& c, const Axes& a, const std::vector<EpisodeRecord>& records, bool test, Rgb colour) {
  std::vector<double> scores, episodes;
  for (const EpisodeRecord& r : records)
    if (r.test == test) {
      scores.push_back(static_cast<double>(r.score));
      episodes.push_back(static_cast<double>(r.episode));
    }
  std::vector<double> avg = moving_average(scores, kWindow);
  for (size_t i = 1; i < avg.size(); ++i) c.line(a.x(episodes[i - 1]), a.y(avg[i - 1]), a.x(episodes[i]), a.y(avg[i]), colour);
  if (avg.size() == 1) c.line(a.x(episodes[0]) - 1, a.y(avg[0]), a.x(episodes[0]) + 1, a.y(avg[0]), colour);
}

}  // namespace

std::vector<double> moving_average(const std::vector<double>& values, size_t window) {
  std::vector<double> out;
  double sum = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    sum += values[i];
    if (i >= window) sum -= values[i - window];
    out.push_back(sum / static_cast<double>(std::min(i + 1, window)));
  }
  return out;
}

void write_learning_curve(const std::string& path, const std::vector<EpisodeRecord>& records) {
  constexpr double kGrid = 1000;  // score grid: Tumble's and Kula World's scores are in hundreds to thousands
  double lo = 0, hi = kGrid, max_x = 10;
  for (const EpisodeRecord& r : records) {
    lo = std::min(lo, static_cast<double>(r.score));
    hi = std::max(hi, static_cast<double>(r.score));
    max_x = std::max(max_x, static_cast<double>(r.episode));
  }
  lo = std::floor(lo / kGrid) * kGrid;
  hi = std::ceil(hi / kGrid) * kGrid;
  Axes a{max_x, lo, hi};
  Canvas c;
  const Rgb grid{210, 210, 210}, axis{0, 0, 0};
  for (double s = lo; s <= hi; s += kGrid) c.line(a.x(0), a.y(s), a.x(max_x), a.y(s), grid);
  double step = std::pow(10.0, std::floor(std::log10(max_x)));
  for (double e = step; e <= max_x; e += step) c.line(a.x(e), a.y(lo), a.x(e), a.y(hi), grid);
  c.line(a.x(0), a.y(lo), a.x(max_x), a.y(lo), axis);
  c.line(a.x(0), a.y(lo), a.x(0), a.y(hi), axis);
  plot(c, a, records, false, {220, 40, 40});
  plot(c, a, records, true, {40, 70, 220});
  std::string error;
  if (!psx::gpu::write_png_rgb(path, c.data(), kWidth, kHeight, error)) throw std::runtime_error(error);
}

}  // namespace psxrl::agents
