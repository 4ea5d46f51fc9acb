// Tabular Q-learning and the ε schedule (src/rl/agents): updates worked by hand from
// Q <- (1 - alpha) Q + alpha (r + gamma max Q'), and the seed's linear ε (§4.2.1).
#include <gtest/gtest.h>

#include "rl/agents/q_agent.h"

using namespace psxrl::agents;
using psxrl::rl::ObsKind;

namespace {

AgentOptions options(double alpha, double gamma) {
  AgentOptions o;
  o.alpha = alpha;
  o.gamma = gamma;
  return o;
}

}  // namespace

TEST(QAgent, UpdateMatchesHandWorkedTransitions) {
  QAgent q(options(0.5, 0.9), 4);
  // A win from state 8 with action 2, reward 0.8: no future, Q(8,2) = 0.5 * 0 + 0.5 * 0.8 = 0.4.
  q.observe({{8}, 2, 0.8, {9}, true});
  EXPECT_DOUBLE_EQ(q.value(8, 2), 0.4);
  // 7 --1--> 8 with reward 0.05: Q(7,1) = 0.5 * 0 + 0.5 * (0.05 + 0.9 * max Q(8,.) = 0.9 * 0.4) = 0.205.
  q.observe({{7}, 1, 0.05, {8}, false});
  EXPECT_DOUBLE_EQ(q.value(7, 1), 0.205);
  // The same again: 0.5 * 0.205 + 0.5 * 0.41 = 0.3075.
  q.observe({{7}, 1, 0.05, {8}, false});
  EXPECT_DOUBLE_EQ(q.value(7, 1), 0.3075);
  // A terminal loss ignores the next state's values: Q(7,3) = 0.5 * -0.1 = -0.05.
  q.observe({{7}, 3, -0.1, {8}, true});
  EXPECT_DOUBLE_EQ(q.value(7, 3), -0.05);
  EXPECT_EQ(q.act({7}, true), 1);
  EXPECT_EQ(q.act({8}, true), 2);
  EXPECT_EQ(q.act({123}, true), 0);  // unseen: every value 0, the first action
  EXPECT_EQ(q.moves(), 4u);
}

TEST(QAgent, OnlyLearnsTheSimpleObservation) {
  EXPECT_NO_THROW(make_agent("q", ObsKind::Simple, 1, 4, {}));
  EXPECT_THROW(make_agent("q", ObsKind::Local, 11, 4, {}), std::invalid_argument);
  EXPECT_THROW(make_agent("sarsa", ObsKind::Simple, 1, 4, {}), std::invalid_argument);
}

// 1.0 -> 0.1 over 10,000 moves: 1.0 - 0.9 * m / 10000 until m = 10000, then 0.1.
TEST(Epsilon, LinearOverTenThousandMovesThenConstant) {
  EXPECT_DOUBLE_EQ(linear_epsilon(0, 1.0, 0.1, 10000), 1.0);
  EXPECT_DOUBLE_EQ(linear_epsilon(5000, 1.0, 0.1, 10000), 0.55);
  EXPECT_DOUBLE_EQ(linear_epsilon(10000, 1.0, 0.1, 10000), 0.1);
  EXPECT_DOUBLE_EQ(linear_epsilon(20000, 1.0, 0.1, 10000), 0.1);
}

TEST(Epsilon, AgentsCountTrainingMoves) {
  AgentOptions o;
  o.epsilon_moves = 4;  // 1.0 - 0.9 * m / 4
  QAgent q(o, 4);
  EXPECT_DOUBLE_EQ(q.epsilon(), 1.0);
  q.observe({{1}, 0, 0, {2}, false});
  q.observe({{2}, 0, 0, {3}, false});
  EXPECT_DOUBLE_EQ(q.epsilon(), 0.55);
  for (int i = 0; i < 3; ++i) q.observe({{3}, 0, 0, {4}, false});
  EXPECT_DOUBLE_EQ(q.epsilon(), 0.1);
}
