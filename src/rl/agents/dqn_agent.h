// Deep Q-learning with LibTorch (seed §3.3.4, §3.3.5, §4.2.1). The agent is built into its own
// plugin, libpsxrl_dqn.so (dqn_agent.cpp and the q_networks.h it alone includes), which
// make_dqn_agent loads on first use (dqn_plugin.cpp): loading LibTorch costs about 0.7 s of
// dynamic linking, which no other command or test should pay.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "rl/agents/agent.h"

namespace psxrl::agents {

// The seed's interpretive networks (§3.3.5). The seed gives the visual network's output (32
// patches of 6x6 = 1152 features) and the episode network's shape (3 inputs, one hidden layer,
// 6 outputs); its Appendix C figures are lost, so the other sizes are ours (docs/agents.md).
// Visual: conv 8x8 stride 4, then conv 4x4 stride 2 down and 3 across: an 80x60 frame becomes
// 19x14, then 6x6.
inline constexpr int kConv1Filters = 16, kConv1Kernel = 8, kConv1Stride = 4;
inline constexpr int kConv2Filters = 32, kConv2Kernel = 4, kConv2StrideY = 2, kConv2StrideX = 3;
inline constexpr int kEpisodeHidden = 16, kEpisodeFeatures = 6;
inline constexpr int kAudioHidden = 32, kAudioFeatures = 8;

// Features the visual network makes of a planes x height x width frame (a valid convolution's
// output is (in - kernel) / stride + 1 per axis); 0 when the frame is too small for it.
constexpr std::int64_t visual_features(std::int64_t height, std::int64_t width) {
  auto out = [](std::int64_t in, int kernel, int stride) { return in < kernel ? 0 : (in - kernel) / stride + 1; };
  std::int64_t h = out(out(height, kConv1Kernel, kConv1Stride), kConv2Kernel, kConv2StrideY);
  std::int64_t w = out(out(width, kConv1Kernel, kConv1Stride), kConv2Kernel, kConv2StrideX);
  return kConv2Filters * h * w;
}

// The seed's agent-local network: `inputs` -> 4 hidden fully connected PReLU layers -> `actions`
// with tanh output (or linear), experience replay, Adam + MSE.
std::unique_ptr<Agent> make_dqn_agent(int inputs, int actions, const AgentOptions& options);

// The same Q network over an observation's arrays. With `interpret` (the visual and multimodal
// observations) each array first goes through its interpretive network (visual, episode, audio)
// and the head learns from their concatenated features; else the head reads the arrays as one
// vector. Arrays of bytes are kept as bytes in the replay memory. Throws std::invalid_argument
// for an array no interpretive network reads.
std::unique_ptr<Agent> make_dqn_agent(const std::vector<rl::Space>& spaces, bool interpret, int actions,
                                      const AgentOptions& options);

// The plugin's two entry points, looked up by name: a stamp of the release and the sizes of the
// types that cross the boundary, which the loader compares with its own so that a plugin left
// over from another build is refused rather than called (constexpr, so each side keeps its own
// values); and the factory behind make_dqn_agent (the caller owns the agent).
struct DqnPluginStamp {
  const char* version;
  std::size_t agent_options, space, agent;
};
constexpr DqnPluginStamp dqn_plugin_stamp() {
  return {PSXRL_VERSION, sizeof(AgentOptions), sizeof(rl::Space), sizeof(Agent)};
}
inline constexpr const char* kDqnPluginFile = "libpsxrl_dqn.so";
inline constexpr const char* kDqnStampSymbol = "psxrl_dqn_stamp";
inline constexpr const char* kDqnFactorySymbol = "psxrl_dqn_make_agent";
using DqnStampFn = const DqnPluginStamp* (*)();
using DqnFactoryFn = Agent* (*)(const std::vector<rl::Space>& spaces, bool interpret, int actions,
                                const AgentOptions& options);

}  // namespace psxrl::agents
