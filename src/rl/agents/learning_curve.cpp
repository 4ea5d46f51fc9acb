// Plotting the learning curve (see learning_curve.h) into an RGB canvas written with libpng; the
// labels use the 5x7 bitmap font of plot_font.h.
#include "rl/agents/learning_curve.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "rl/agents/plot_font.h"
#include "util/png_writer.h"

namespace psxrl::agents {

namespace {

constexpr int kWidth = 640, kHeight = 360;
// Plot area margins: room for the score labels on the left, the episode labels and the axis
// title below, the legend above.
constexpr int kLeft = 56, kRight = 16, kTop = 24, kBottom = 40;
constexpr double kGrid = 1000;  // score grid: Tumble's and Kula World's scores are in hundreds to thousands
constexpr size_t kWindow = 5;   // the seed's Fig. 4.6 averages over 5 episodes

struct Rgb {
  std::uint8_t r, g, b;
};
constexpr Rgb kGray{210, 210, 210}, kBlack{0, 0, 0}, kRed{220, 40, 40}, kBlue{40, 70, 220};

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
  // `text` with its top-left corner at (x, y).
  void text(int x, int y, const std::string& text, Rgb c) {
    for (char ch : text) {
      if (const char* rows = glyph(ch))
        for (int gy = 0; gy < kGlyphHeight; ++gy)
          for (int gx = 0; gx < kGlyphWidth; ++gx)
            if (rows[gy * kGlyphWidth + gx] == '#') set(x + gx, y + gy, c);
      x += kGlyphAdvance;
    }
  }
  std::vector<std::uint8_t> take() { return std::move(pixels_); }

 private:
  std::vector<std::uint8_t> pixels_;
};

// Plot area mapping: episode 0..max_x to the left..right edge, score lo..hi bottom to top.
struct Axes {
  double max_x, lo, hi;
  int x(double episode) const {
    return kLeft + static_cast<int>(std::lround(episode / max_x * (kWidth - kLeft - kRight)));
  }
  int y(double score) const {
    return kHeight - kBottom - static_cast<int>(std::lround((score - lo) / (hi - lo) * (kHeight - kTop - kBottom)));
  }
};

std::string number(double v) { return std::to_string(std::llround(v)); }

void plot(Canvas& c, const Axes& a, const std::vector<EpisodeRecord>& records, bool test, Rgb colour) {
  std::vector<double> scores, episodes;
  for (const EpisodeRecord& r : records)
    if (r.test == test && !r.heldout) {  // held-out tests are the generalisation study's (metrics.csv)
      scores.push_back(static_cast<double>(r.score));
      episodes.push_back(static_cast<double>(r.episode));
    }
  std::vector<double> avg = moving_average(scores, kWindow);
  for (size_t i = 1; i < avg.size(); ++i) c.line(a.x(episodes[i - 1]), a.y(avg[i - 1]), a.x(episodes[i]), a.y(avg[i]), colour);
  if (avg.size() == 1) c.line(a.x(episodes[0]) - 1, a.y(avg[0]), a.x(episodes[0]) + 1, a.y(avg[0]), colour);
}

// Grid, axes, ticks with their labels, axis titles and the legend.
void frame(Canvas& c, const Axes& a) {
  for (double s = a.lo; s <= a.hi; s += kGrid) c.line(a.x(0), a.y(s), a.x(a.max_x), a.y(s), kGray);
  for (double e : episode_ticks(a.max_x)) {
    if (e > 0) c.line(a.x(e), a.y(a.lo), a.x(e), a.y(a.hi), kGray);
    c.line(a.x(e), a.y(a.lo), a.x(e), a.y(a.lo) + 4, kBlack);
    std::string label = number(e);
    c.text(a.x(e) - text_width(label) / 2, a.y(a.lo) + 8, label, kBlack);
  }
  for (double s : score_ticks(a.lo, a.hi)) {
    c.line(a.x(0) - 4, a.y(s), a.x(0), a.y(s), kBlack);
    std::string label = number(s);
    c.text(a.x(0) - 7 - text_width(label), a.y(s) - kGlyphHeight / 2, label, kBlack);
  }
  c.line(a.x(0), a.y(a.lo), a.x(a.max_x), a.y(a.lo), kBlack);
  c.line(a.x(0), a.y(a.lo), a.x(0), a.y(a.hi), kBlack);
  const std::string episode = "EPISODE", score = "SCORE";
  c.text(a.x(a.max_x / 2) - text_width(episode) / 2, kHeight - 14, episode, kBlack);
  c.text(4, 8, score, kBlack);
  const std::string train = "TRAINING", test = "TEST", average = "MOVING AVERAGE OF 5 EPISODES";
  int x = kWidth - kRight - text_width(train + test + average) - 3 * 16 - 2 * 8;
  c.text(x, 8, average, kBlack);
  x += text_width(average) + 16;
  c.line(x, 11, x + 12, 11, kRed);
  c.text(x + 16, 8, train, kBlack);
  x += 16 + text_width(train) + 16;
  c.line(x, 11, x + 12, 11, kBlue);
  c.text(x + 16, 8, test, kBlack);
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

std::vector<double> episode_ticks(double max_episode) {
  double step = std::pow(10.0, std::floor(std::log10(max_episode)));
  if (max_episode / step < 3) step /= 2;
  std::vector<double> ticks;
  for (int i = 0; i * step <= max_episode; ++i) ticks.push_back(i * step);
  return ticks;
}

std::vector<double> score_ticks(double lo, double hi) {
  for (double scale = kGrid;; scale *= 10) {
    for (double m : {1.0, 2.0, 5.0}) {
      double step = m * scale, first = std::ceil(lo / step) * step;
      if (std::floor((hi - first) / step) + 1 > 8) continue;
      std::vector<double> ticks;
      for (double s = first; s <= hi; s += step) ticks.push_back(s);
      return ticks;
    }
  }
}

int text_width(const std::string& text) {
  return text.empty() ? 0 : static_cast<int>(text.size()) * kGlyphAdvance - (kGlyphAdvance - kGlyphWidth);
}

RgbImage render_learning_curve(const std::vector<EpisodeRecord>& records) {
  double lo = 0, hi = kGrid, max_x = 10;
  for (const EpisodeRecord& r : records) {
    lo = std::min(lo, static_cast<double>(r.score));
    hi = std::max(hi, static_cast<double>(r.score));
    max_x = std::max(max_x, static_cast<double>(r.episode));
  }
  Axes a{max_x, std::floor(lo / kGrid) * kGrid, std::ceil(hi / kGrid) * kGrid};
  Canvas c;
  frame(c, a);
  plot(c, a, records, false, kRed);
  plot(c, a, records, true, kBlue);
  return {kWidth, kHeight, c.take()};
}

void write_learning_curve(const std::string& path, const std::vector<EpisodeRecord>& records) {
  RgbImage image = render_learning_curve(records);
  std::string error;
  if (!psx::write_png_rgb(path, image.rgb.data(), image.width, image.height, error)) throw std::runtime_error(error);
}

}  // namespace psxrl::agents
