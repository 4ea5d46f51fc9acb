// Checkpoints (src/rl/agents/checkpoint.h): a saved agent, read back into a fresh one made with
// another seed, acts and learns exactly as the original; damaged files and foreign policies are
// refused with a reason.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "rl/agents/checkpoint.h"
#include "rl/agents/dqn_agent.h"

using namespace psxrl::agents;
using psxrl::rl::ObsKind;

namespace {

std::string temp_file(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("psxrl_agent_ckpt_" + name + "_" + std::to_string(getpid())))
      .string();
}

std::vector<float> random_state(Rng& rng) {
  std::vector<float> s(11);
  for (float& v : s) v = static_cast<float>(rng.uniform() * 2 - 1);
  return s;
}

// `n` ε-greedy moves on made-up states, each observed and learnt from.
void drive(Agent& agent, Rng& rng, int n) {
  for (int i = 0; i < n; ++i) {
    std::vector<float> s = random_state(rng), s2 = random_state(rng);
    int a = agent.act(s, false);
    agent.observe({s, a, rng.uniform() - 0.5, s2, i % 7 == 0});
    agent.learn();
  }
}

Checkpoint round_trip(const Agent& agent, const std::string& name) {
  Checkpoint c;
  c.meta = {{"game", "tumble"}, {"network", agent.network()}};
  ByteWriter w;
  agent.save(w);
  c.agent = w.take_string();
  std::string path = temp_file(name);
  write_checkpoint(path, c);
  Checkpoint back = read_checkpoint(path);
  std::filesystem::remove(path);
  return back;
}

void expect_same_future(Agent& a, Agent& b) {
  Rng states(77);
  for (int i = 0; i < 50; ++i) {
    std::vector<float> s = random_state(states);
    ASSERT_EQ(a.act(s, true), b.act(s, true)) << "greedy action " << i;
  }
  Rng ra(5), rb(5);  // both go on learning from the same moves
  drive(a, ra, 30);
  drive(b, rb, 30);
  EXPECT_EQ(a.moves(), b.moves());
  EXPECT_EQ(a.epsilon(), b.epsilon());
  EXPECT_EQ(a.last_loss(), b.last_loss());
  for (int i = 0; i < 50; ++i) {
    std::vector<float> s = random_state(states);
    ASSERT_EQ(a.act(s, true), b.act(s, true)) << "greedy action after more learning " << i;
  }
}

}  // namespace

TEST(Checkpoint, DqnRoundTripGivesTheSameActionsAndLearning) {
  AgentOptions o;
  o.seed = 3;
  o.epochs = 2;  // a short test; the epoch count does not change what is saved
  o.target_network = true;
  o.target_sync = 10;
  auto a = make_dqn_agent(11, 4, o);
  Rng rng(1);
  drive(*a, rng, 120);
  Checkpoint c = round_trip(*a, "dqn");
  o.seed = 99;  // different initial weights and generator: everything must come from the file
  auto b = make_dqn_agent(11, 4, o);
  ASSERT_EQ(c.meta.at("network"), b->network());
  ByteReader r(c.agent, "agent");
  b->load(r);
  EXPECT_TRUE(r.done());
  expect_same_future(*a, *b);
}

TEST(Checkpoint, QRoundTripGivesTheSameActions) {
  AgentOptions o;
  o.seed = 4;
  auto a = make_agent("q", ObsKind::Simple, 1, 4, o);
  Rng rng(2);
  for (int i = 0; i < 500; ++i) {
    std::vector<float> s{static_cast<float>(rng.below(40))}, s2{static_cast<float>(rng.below(40))};
    a->observe({s, a->act(s, false), rng.uniform() - 0.5, s2, false});
  }
  Checkpoint c = round_trip(*a, "q");
  o.seed = 8;
  auto b = make_agent("q", ObsKind::Simple, 1, 4, o);
  ByteReader r(c.agent, "agent");
  b->load(r);
  for (int s = 0; s < 40; ++s) EXPECT_EQ(a->act({float(s)}, true), b->act({float(s)}, true)) << "state " << s;
  for (int i = 0; i < 20; ++i) EXPECT_EQ(a->act({1}, false), b->act({1}, false));  // same generator state
}

TEST(Checkpoint, DamagedFilesAreRefusedWithAReason) {
  Checkpoint c;
  c.meta = {{"game", "tumble"}};
  c.agent = std::string(100, 'a');
  std::string path = temp_file("damaged");
  write_checkpoint(path, c);
  auto size = std::filesystem::file_size(path);
  auto expect_refusal = [&](const std::string& why) {
    try {
      read_checkpoint(path);
      ADD_FAILURE() << "accepted a file that should say: " << why;
    } catch (const CorruptCheckpoint& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  std::filesystem::resize_file(path, size - 10);
  expect_refusal("truncated");
  write_checkpoint(path, c);
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(size - 20));
    f.put('b');  // inside the agent bytes
  }
  expect_refusal("checksum mismatch");
  std::ofstream(path, std::ios::trunc) << "not a checkpoint at all, just some text to read";
  expect_refusal("expected the magic PSXRLCKP");
  std::filesystem::remove(path);
  expect_refusal("cannot open file");
}

TEST(Checkpoint, PolicyForAnotherGameObservationOrNetworkIsRefused) {
  Settings meta = {{"game", "tumble"}, {"obs", "simple"}, {"integration_hash", "abc"}, {"network", "n1"}};
  EXPECT_EQ(policy_mismatch(meta, "tumble", "simple", "abc", "n1"), "");
  EXPECT_EQ(policy_mismatch(meta, "kula", "simple", "abc", "n1"), "it was trained for game 'tumble', not 'kula'");
  EXPECT_EQ(policy_mismatch(meta, "tumble", "local", "abc", "n1"),
            "it was trained on the 'simple' observation, not 'local'");
  EXPECT_NE(policy_mismatch(meta, "tumble", "simple", "abd", "n1").find("another version"), std::string::npos);
  EXPECT_NE(policy_mismatch(meta, "tumble", "simple", "abc", "n2").find("its network is 'n1'"), std::string::npos);
}
