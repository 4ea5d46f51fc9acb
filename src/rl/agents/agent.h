// Learning agents behind one interface (seed §3.3): act on an observation, observe a transition,
// learn, save and load. Agents see environments only through observations (DESIGN.md "Agents see
// environments, never the console"); LibTorch stays inside dqn_agent.cpp.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rl/agents/rng.h"
#include "rl/agents/serialize.h"
#include "rl/observation.h"

namespace psxrl::agents {

// How an ε-greedy agent picks its exploratory moves: uniformly (§3.3.1), or in proportion to the
// seed's Eq. 4.1 (§4.2.4).
enum class Exploration { Epsilon, QWeighted };
inline constexpr const char* kExplorationList = "epsilon, q-weighted";
Exploration parse_exploration(const std::string& name);  // throws std::invalid_argument
const char* exploration_name(Exploration e);

// Every option any agent takes; each agent reads the ones it needs. Defaults are the seed's.
struct AgentOptions {
  double gamma = 0.9;
  std::uint64_t seed = 0;
  // ε-greedy (§3.3.1, §4.2.1): linear from start to end over `epsilon_moves` training moves.
  double epsilon_start = 1.0, epsilon_end = 0.1;
  std::uint64_t epsilon_moves = 10000;
  Exploration exploration = Exploration::Epsilon;
  double alpha = 0.5;  // tabular learning rate (the seed does not state one)
  // DQN (§3.3.4, §4.2.1).
  double lr = 0.0025;  // default_lr(): 0.004 for the visual and multimodal networks
  int hidden = 32;  // width of the 4 hidden layers (the seed's Appendix C figure is lost)
  std::size_t replay_capacity = 5000, batch = 80;
  int epochs = 15;
  bool linear_output = false;   // the seed's tanh output unless set (§4.2.5)
  bool target_network = false;  // beyond the seed: a target net synced every target_sync moves
  std::uint64_t target_sync = 500;
  bool double_dqn = false;      // beyond the seed: Double DQN targets (implies a target network)
};

// ε after `moves` training moves: linear from start to end, then constant.
double linear_epsilon(std::uint64_t moves, double start, double end, std::uint64_t over);

// Eq. 4.1: the probability of each exploratory action a is proportional to
// K(a) = Q(s|a) + noise[a] * range_a'(Q(s|a')), noise[a] one draw of rand(-0.5, 0.5) per action.
// The seed does not say what a negative K means; a probability cannot be negative, so such an
// action weighs 0, and when no action weighs more than 0 the choice is uniform.
std::vector<double> q_weighted_probabilities(const std::vector<double>& q, const std::vector<double>& noise);

// One move's experience (s, a, r, s'), the observations flattened to floats (features()).
struct Transition {
  std::vector<float> state;
  int action = 0;
  double reward = 0;
  std::vector<float> next_state;
  bool terminal = false;  // won or lost: no future value (a move cap is not terminal)
};

// Every array of an observation, in order, as floats (simple's index is exact below 2^24).
std::vector<float> features(const rl::Observation& obs);

class Agent {
 public:
  Agent(const AgentOptions& options, int actions) : options_(options), actions_(actions), rng_(options.seed) {}
  virtual ~Agent() = default;

  virtual std::string name() const = 0;
  // The shape of what the agent learns (inputs, layers, outputs): a policy refuses to load into
  // an agent whose network() differs.
  virtual std::string network() const = 0;
  // An action for `state`: the best known when `greedy`, else ε-greedy (options.exploration).
  virtual int act(const std::vector<float>& state, bool greedy) = 0;
  // Q(state, a) for every action (all 0 for an agent that learns none).
  virtual std::vector<double> q_values(const std::vector<float>& state) = 0;
  // How many numbers the agent learns (network parameters or table entries).
  virtual std::uint64_t parameter_count() const = 0;
  // A training move's transition; counts the move for the ε schedule.
  virtual void observe(const Transition& t) = 0;
  // The update after a training move (DQN trains one replay batch; tabular Q learns in observe).
  virtual void learn() {}
  virtual double last_loss() const { return 0; }
  virtual double epsilon() const;
  std::uint64_t moves() const { return moves_; }
  // Learner updates made by this object (not saved): tabular Q's table updates, DQN's gradient
  // steps (one per epoch of a replay batch). For throughput figures.
  std::uint64_t updates() const { return updates_; }

  // The whole learning state (parameters, optimiser, replay memory, generator, move count).
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

 protected:
  virtual void save_state(ByteWriter& w) const = 0;
  virtual void load_state(ByteReader& r) = 0;
  bool explore() { return rng_.uniform() < epsilon(); }
  int random_action() { return static_cast<int>(rng_.below(static_cast<std::uint64_t>(actions_))); }
  // An ε-greedy agent's move once explore() said so: uniform, or Eq. 4.1 (one noise draw per
  // action, then one to pick).
  int exploratory_action(const std::vector<float>& state);

  AgentOptions options_;
  int actions_;
  Rng rng_;
  std::uint64_t moves_ = 0;
  std::uint64_t updates_ = 0;
};

inline constexpr const char* kAgentList = "random, q, dqn";
// `name` is random, q or dqn; `spaces` the environment's observation arrays. Throws
// std::invalid_argument for an unknown agent or an observation it cannot use.
std::unique_ptr<Agent> make_agent(const std::string& name, rl::ObsKind obs, const std::vector<rl::Space>& spaces,
                                  int actions, const AgentOptions& options);
// The same for an observation known only by its length (features()): one float array, so not
// the visual or multimodal observation, whose networks need the arrays' shapes.
std::unique_ptr<Agent> make_agent(const std::string& name, rl::ObsKind obs, int inputs, int actions,
                                  const AgentOptions& options);
// The observation an agent uses unless told otherwise: q and random simple, dqn local.
std::string default_obs(const std::string& agent);
// The seed's Adam learning rate (§4.2.1): 0.004 for the complex (visual, multimodal) networks,
// 0.0025 for the others.
double default_lr(const std::string& obs);

}  // namespace psxrl::agents
