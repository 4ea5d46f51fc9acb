// Observations by name, each with a fixed shape and dtype: the one table the CLI, Python and the
// agents share (docs/environments.md). The encoders here are pure functions over a level map,
// a frame or audio samples, so each is testable on hand-worked cases.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/audio_fifo.h"
#include "rl/level_map.h"

namespace psxrl::rl {

enum class DType { U8, I64, F32 };
const char* dtype_name(DType d);
size_t dtype_size(DType d);

// Name, shape and dtype of one observation array, with its value bounds.
struct Space {
  std::string name;
  std::vector<std::int64_t> shape;
  DType dtype = DType::F32;
  double low = 0, high = 0;
  size_t elements() const;
  size_t bytes() const { return elements() * dtype_size(dtype); }
};

// One array of an observation: its space and data valid until the environment's next call.
struct ObsPart {
  const Space* space = nullptr;
  const void* data = nullptr;
};
using Observation = std::vector<ObsPart>;

enum class ObsKind { Simple, Local, Visual, Audio, Episode, Ram, Rumble, Multimodal };
// Throws std::invalid_argument listing the kinds for an unknown name.
ObsKind parse_obs_kind(const std::string& name);
const char* obs_kind_name(ObsKind k);
inline constexpr const char* kObsKindList = "simple, local, visual, audio, episode, ram, rumble, multimodal";

// Numeric value of a map tile in the agent-local crop: how desirable the square is, on one line
// from deadly (-1) to the goal (+1), as the seed's Figure 3.8 orders them.
float tile_value(Tile t);

// The seed's simple state: (x, y, z) -> 4*w*y + 4*x + z, with x, y clamped into the map.
std::int64_t simple_index(const LevelMap& map, int x, int y, int facing);

// The agent-local crop: rows from `ahead` tiles in front of the ball down to `behind` tiles behind
// it, each from `side` tiles to its left to `side` to its right, rotated so "ahead" is up.
// Writes (ahead + behind + 1) * (2 * side + 1) tile values.
void local_crop(const LevelMap& map, int x, int y, int facing, int ahead, int behind, int side, float* out);

// The displayed frame (RGB888, width x height) cropped to (cx, cy, cw, ch) and box-filtered to
// out_w x out_h, as separate planes: 3 (R, G, B) or 1 (grayscale, ITU-R BT.601 luma).
void visual_planes(const std::uint8_t* rgb, int width, int height, int cx, int cy, int cw, int ch, int out_w, int out_h,
                   bool gray, std::uint8_t* out);

// MFCCs (25 ms frames, 11.6 ms step, 13 coefficients) of the audio with leading and trailing
// samples below `threshold` cropped (the seed's amplitude-based cropping), as `frames` rows of 13;
// missing rows are zero, extra rows are dropped.
void audio_mfcc(const std::vector<psx::StereoSample>& samples, int threshold, int frames, float* out);
inline constexpr int kMfccCoefficients = 13;

}  // namespace psxrl::rl
