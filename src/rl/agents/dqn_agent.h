// Deep Q-learning with LibTorch (seed §3.3.4, §4.2.1); the only file that includes torch is
// dqn_agent.cpp, so nothing else in the project compiles against it.
#pragma once
#include <memory>

#include "rl/agents/agent.h"

namespace psxrl::agents {

// The seed's agent-local network: `inputs` -> 4 hidden fully connected PReLU layers -> `actions`
// with tanh output (or linear), experience replay, Adam + MSE.
std::unique_ptr<Agent> make_dqn_agent(int inputs, int actions, const AgentOptions& options);

}  // namespace psxrl::agents
