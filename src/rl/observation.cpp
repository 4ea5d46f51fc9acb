// Observation encoders (see observation.h).
#include "rl/observation.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "spu/audio_features.h"

namespace psxrl::rl {

const char* dtype_name(DType d) { return d == DType::U8 ? "uint8" : d == DType::I64 ? "int64" : "float32"; }

size_t dtype_size(DType d) { return d == DType::U8 ? 1 : d == DType::I64 ? 8 : 4; }

size_t Space::elements() const {
  size_t n = 1;
  for (auto s : shape) n *= static_cast<size_t>(s);
  return n;
}

namespace {
constexpr std::pair<const char*, ObsKind> kKinds[] = {
    {"simple", ObsKind::Simple}, {"local", ObsKind::Local},   {"visual", ObsKind::Visual},
    {"audio", ObsKind::Audio},   {"episode", ObsKind::Episode}, {"ram", ObsKind::Ram},
    {"rumble", ObsKind::Rumble}, {"multimodal", ObsKind::Multimodal}};
}  // namespace

ObsKind parse_obs_kind(const std::string& name) {
  for (const auto& [n, k] : kKinds)
    if (name == n) return k;
  throw std::invalid_argument("unknown observation '" + name + "' (expected one of " + kObsKindList + ")");
}

const char* obs_kind_name(ObsKind k) {
  for (const auto& [n, kind] : kKinds)
    if (k == kind) return n;
  return "?";
}

float tile_value(Tile t) {
  switch (t) {
    case Tile::Void: return -1.0f;
    case Tile::Spikes: return -0.5f;
    case Tile::Crumbling: return 0.25f;
    case Tile::Floor:
    case Tile::Start: return 0.5f;
    case Tile::Coin:
    case Tile::Fruit:
    case Tile::Key: return 0.75f;
    case Tile::Exit: return 1.0f;
  }
  return -1.0f;
}

std::int64_t simple_index(const LevelMap& map, int x, int y, int facing) {
  x = std::clamp(x, 0, map.width - 1);
  y = std::clamp(y, 0, map.height - 1);
  return 4LL * map.width * y + 4LL * x + (facing & 3);
}

void local_crop(const LevelMap& map, int x, int y, int facing, int ahead, int behind, int side, float* out) {
  // Unit steps for "forward" and "to the right" per facing (north is row - 1, east is x + 1).
  static constexpr int kFwd[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  const int* f = kFwd[facing & 3];
  const int* r = kFwd[(facing + 1) & 3];
  for (int d = ahead; d >= -behind; --d)
    for (int c = -side; c <= side; ++c) *out++ = tile_value(map.at(x + d * f[0] + c * r[0], y + d * f[1] + c * r[1]));
}

void visual_planes(const std::uint8_t* rgb, int width, int height, int cx, int cy, int cw, int ch, int out_w, int out_h,
                   bool gray, std::uint8_t* out) {
  const size_t plane = static_cast<size_t>(out_w) * out_h;
  for (int oy = 0; oy < out_h; ++oy) {
    int y0 = cy + oy * ch / out_h, y1 = std::max(y0 + 1, cy + (oy + 1) * ch / out_h);
    for (int ox = 0; ox < out_w; ++ox) {
      int x0 = cx + ox * cw / out_w, x1 = std::max(x0 + 1, cx + (ox + 1) * cw / out_w);
      // The box's pixels outside the frame count as black.
      const unsigned n = static_cast<unsigned>((y1 - y0) * (x1 - x0));
      const int x_end = std::min(x1, width), y_end = std::min(y1, height);
      unsigned sum[3] = {0, 0, 0};
      for (int y = y0; y < y_end; ++y) {
        const std::uint8_t* p = rgb + (static_cast<size_t>(y) * width + x0) * 3;
        unsigned r = 0, g = 0, b = 0;  // in registers: the row's sums
        for (int x = x0; x < x_end; ++x, p += 3) r += p[0], g += p[1], b += p[2];
        sum[0] += r, sum[1] += g, sum[2] += b;
      }
      size_t at = static_cast<size_t>(oy) * out_w + ox;
      if (gray) {
        // BT.601 luma in integer weights summing to 1000.
        out[at] = static_cast<std::uint8_t>((299u * sum[0] + 587u * sum[1] + 114u * sum[2]) / (1000u * n));
      } else {
        for (int k = 0; k < 3; ++k) out[k * plane + at] = static_cast<std::uint8_t>(sum[k] / n);
      }
    }
  }
}

void audio_mfcc(const std::vector<psx::StereoSample>& samples, int threshold, int frames, float* out) {
  std::fill(out, out + static_cast<size_t>(frames) * kMfccCoefficients, 0.0f);
  auto loud = [&](const psx::StereoSample& s) { return std::abs(s.left) > threshold || std::abs(s.right) > threshold; };
  auto first = std::find_if(samples.begin(), samples.end(), loud);
  if (first == samples.end()) return;
  auto last = std::find_if(samples.rbegin(), samples.rend(), loud).base();
  Eigen::MatrixXf m = psx::spu::mfcc(&*first, static_cast<size_t>(last - first));
  int rows = std::min(frames, static_cast<int>(m.rows()));
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < kMfccCoefficients; ++c) out[r * kMfccCoefficients + c] = m(r, c);
}

}  // namespace psxrl::rl
