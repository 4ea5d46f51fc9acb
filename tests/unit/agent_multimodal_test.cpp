// The DQN agent's multimodal and visual networks (seed §3.3.5, src/rl/agents/q_networks.h):
// the visual network's 1152 features, parameter counts summed by hand from the documented layer
// sizes, 4 Q-values, a checkpoint that gives back the same Q-values, and a short training run on
// Tumble's multimodal observation.
#include <gtest/gtest.h>

#include <filesystem>

#include "rl/agents/dqn_agent.h"
#include "rl/agents/trainer.h"

using namespace psxrl::agents;
using psxrl::rl::DType;
using psxrl::rl::ObsKind;
using psxrl::rl::Space;

namespace {

// Tumble's multimodal observation (docs/environments.md): visual [3, 60, 80] bytes, episode [3],
// audio [64, 13] MFCC rows.
std::vector<Space> multimodal_spaces(int planes = 3) {
  return {{"visual", {planes, 60, 80}, DType::U8, 0, 255},
          {"episode", {3}, DType::F32, -1e9, 1e9},
          {"audio", {64, 13}, DType::F32, -1e9, 1e9}};
}

std::vector<float> random_state(const std::vector<Space>& spaces, Rng& rng) {
  std::vector<float> s;
  for (const Space& sp : spaces)
    for (size_t i = 0; i < sp.elements(); ++i)
      s.push_back(sp.dtype == DType::U8 ? static_cast<float>(rng.below(256)) : static_cast<float>(rng.uniform() * 4 - 2));
  return s;
}

AgentOptions small_options(std::uint64_t seed) {
  AgentOptions o;
  o.seed = seed;
  o.lr = default_lr("multimodal");
  o.batch = 8;   // small batches keep the convolutions quick; the sizes do not change what is saved
  o.epochs = 2;
  return o;
}

}  // namespace

TEST(Multimodal, VisualNetworkFlattensTo32PatchesOf6x6) {
  // conv 8x8 stride 4: (60 - 8) / 4 + 1 = 14 rows, (80 - 8) / 4 + 1 = 19 columns;
  // conv 4x4 stride 2 down, 3 across: (14 - 4) / 2 + 1 = 6, (19 - 4) / 3 + 1 = 6.
  EXPECT_EQ(visual_features(60, 80), 32 * 6 * 6);
  EXPECT_EQ(visual_features(60, 80), 1152);
  // The smallest frame it reads: 20 -> (20 - 8) / 4 + 1 = 4 -> 1 patch per axis.
  EXPECT_EQ(visual_features(20, 20), 32);
  EXPECT_EQ(visual_features(19, 80), 0);
}

TEST(Multimodal, ParameterCountsAreTheLayerSums) {
  const std::uint64_t prelu = 1;  // one learnt slope per PReLU module
  const std::uint64_t conv1 = 16 * 3 * 8 * 8 + 16, conv2 = 32 * 16 * 4 * 4 + 32;
  const std::uint64_t visual = conv1 + prelu + conv2 + prelu;                   // 11314
  const std::uint64_t episode = (3 * 16 + 16) + prelu + (16 * 6 + 6) + prelu;   // 168
  const std::uint64_t audio = (832 * 32 + 32) + prelu + (32 * 8 + 8) + prelu;   // 26922
  auto head = [&](std::uint64_t in) { return (in * 32 + 32) + 3 * (32 * 32 + 32) + 4 * prelu + (32 * 4 + 4); };
  EXPECT_EQ(visual + episode + audio + head(1152 + 6 + 8), 79052u);

  AgentOptions o;
  auto multimodal = make_agent("dqn", ObsKind::Multimodal, multimodal_spaces(), 4, o);
  EXPECT_EQ(multimodal->parameter_count(), 79052u);
  std::vector<Space> visual_only{multimodal_spaces()[0]};
  EXPECT_EQ(make_agent("dqn", ObsKind::Visual, visual_only, 4, o)->parameter_count(), visual + head(1152));
  // Gray frames: one plane into the first convolution.
  std::uint64_t gray_conv1 = 16 * 1 * 8 * 8 + 16;
  EXPECT_EQ(make_agent("dqn", ObsKind::Multimodal, multimodal_spaces(1), 4, o)->parameter_count(),
            79052u - conv1 + gray_conv1);
  // The agent-local network: 11 inputs, 4 hidden layers of 32, 4 outputs.
  EXPECT_EQ(make_dqn_agent(11, 4, o)->parameter_count(), head(11));
}

TEST(Multimodal, GivesOneBoundedQValuePerAction) {
  auto agent = make_agent("dqn", ObsKind::Multimodal, multimodal_spaces(), 4, small_options(1));
  Rng rng(5);
  std::vector<double> q = agent->q_values(random_state(multimodal_spaces(), rng));
  ASSERT_EQ(q.size(), 4u);
  for (double v : q) {
    EXPECT_GT(v, -1.0);  // tanh output
    EXPECT_LT(v, 1.0);
  }
  EXPECT_NE(agent->network().find("visual[3x60x80] episode[3] audio[64x13] -> mlp 1166-32-32-32-32-4"),
            std::string::npos)
      << agent->network();
}

TEST(Multimodal, CheckpointRoundTripGivesIdenticalQValues) {
  std::vector<Space> spaces = multimodal_spaces();
  auto a = make_agent("dqn", ObsKind::Multimodal, spaces, 4, small_options(2));
  Rng rng(7);
  for (int i = 0; i < 12; ++i) {
    std::vector<float> s = random_state(spaces, rng), s2 = random_state(spaces, rng);
    a->observe({s, a->act(s, false), rng.uniform() - 0.5, s2, i % 5 == 4});
    a->learn();
  }
  ByteWriter w;
  a->save(w);
  auto b = make_agent("dqn", ObsKind::Multimodal, spaces, 4, small_options(99));  // other weights
  std::string bytes = w.take_string();
  ByteReader r(bytes, "agent");
  b->load(r);
  EXPECT_TRUE(r.done());
  for (int i = 0; i < 5; ++i) {
    std::vector<float> s = random_state(spaces, rng);
    EXPECT_EQ(a->q_values(s), b->q_values(s)) << "state " << i;
  }
  // The replay memory and generator came back too: the next batch trains both the same way.
  a->learn();
  b->learn();
  EXPECT_EQ(a->last_loss(), b->last_loss());
}

TEST(Multimodal, RefusesWhatItCannotRead) {
  AgentOptions o;
  EXPECT_THROW(make_agent("dqn", ObsKind::Multimodal, 15235, 4, o), std::invalid_argument);  // shapes unknown
  std::vector<Space> rumble{{"rumble", {2}, DType::U8, 0, 255}};
  EXPECT_THROW(make_agent("dqn", ObsKind::Multimodal, rumble, 4, o), std::invalid_argument);
  std::vector<Space> tiny{{"visual", {3, 12, 16}, DType::U8, 0, 255}};
  EXPECT_THROW(make_agent("dqn", ObsKind::Visual, tiny, 4, o), std::invalid_argument);
}

TEST(Multimodal, DefaultLearningRatesAreTheSeeds) {
  EXPECT_EQ(default_lr("multimodal"), 0.004);
  EXPECT_EQ(default_lr("visual"), 0.004);
  EXPECT_EQ(default_lr("local"), 0.0025);
}

TEST(Multimodal, TrainsOnTumbleForAFewDozenMoves) {
  auto dir = std::filesystem::temp_directory_path() / ("psxrl_agent_multimodal_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  TrainConfig c;
  c.agent = "dqn";
  c.env.obs = "multimodal";
  c.env.max_moves = 20;
  c.options = small_options(0);
  c.episodes = 2;
  c.test_every = 2;
  c.seed = 3;
  c.out = dir.string();
  Trainer t(c);
  t.run(nullptr);
  ASSERT_EQ(t.records().size(), 2u);
  EXPECT_GT(t.records()[0].moves, 0u);
  EXPECT_EQ(t.agent().moves(), t.records()[0].moves);  // the second episode is a greedy test
  EXPECT_TRUE(std::filesystem::exists(dir / "checkpoint.psxrl"));
  std::filesystem::remove_all(dir);
}
