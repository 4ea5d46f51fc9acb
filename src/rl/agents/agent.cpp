// The agent interface's shared parts, the random agent and tabular Q-learning (seed §3.3.3).
#include "rl/agents/agent.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "rl/agents/dqn_agent.h"
#include "rl/agents/q_agent.h"

namespace psxrl::agents {

Exploration parse_exploration(const std::string& name) {
  if (name == "epsilon") return Exploration::Epsilon;
  if (name == "q-weighted") return Exploration::QWeighted;
  throw std::invalid_argument("unknown exploration '" + name + "' (expected " + kExplorationList + ")");
}

const char* exploration_name(Exploration e) { return e == Exploration::QWeighted ? "q-weighted" : "epsilon"; }

std::vector<double> q_weighted_probabilities(const std::vector<double>& q, const std::vector<double>& noise) {
  if (q.empty()) return {};
  auto [lo, hi] = std::minmax_element(q.begin(), q.end());
  double range = *hi - *lo;
  std::vector<double> p(q.size());
  double sum = 0;
  for (size_t a = 0; a < q.size(); ++a) sum += p[a] = std::max(0.0, q[a] + noise.at(a) * range);
  for (double& v : p) v = sum > 0 ? v / sum : 1.0 / static_cast<double>(q.size());
  return p;
}

double linear_epsilon(std::uint64_t moves, double start, double end, std::uint64_t over) {
  if (over == 0 || moves >= over) return end;
  return start + (end - start) * static_cast<double>(moves) / static_cast<double>(over);
}

std::vector<float> features(const rl::Observation& obs) {
  std::vector<float> out;
  for (const rl::ObsPart& part : obs) {
    size_t n = part.space->elements();
    switch (part.space->dtype) {
      case rl::DType::F32: {
        const float* p = static_cast<const float*>(part.data);
        out.insert(out.end(), p, p + n);
        break;
      }
      case rl::DType::I64: {
        const std::int64_t* p = static_cast<const std::int64_t*>(part.data);
        for (size_t i = 0; i < n; ++i) out.push_back(static_cast<float>(p[i]));
        break;
      }
      case rl::DType::U8: {
        const std::uint8_t* p = static_cast<const std::uint8_t*>(part.data);
        for (size_t i = 0; i < n; ++i) out.push_back(static_cast<float>(p[i]));
        break;
      }
    }
  }
  return out;
}

double Agent::epsilon() const {
  return linear_epsilon(moves_, options_.epsilon_start, options_.epsilon_end, options_.epsilon_moves);
}

int Agent::exploratory_action(const std::vector<float>& state) {
  if (options_.exploration == Exploration::Epsilon) return random_action();
  std::vector<double> noise(static_cast<size_t>(actions_));
  for (double& n : noise) n = rng_.uniform() - 0.5;
  std::vector<double> p = q_weighted_probabilities(q_values(state), noise);
  double u = rng_.uniform();
  for (int a = 0; a < actions_ - 1; ++a) {
    if (u < p[static_cast<size_t>(a)]) return a;
    u -= p[static_cast<size_t>(a)];
  }
  return actions_ - 1;  // what rounding leaves of the sum
}

void Agent::save(ByteWriter& w) const {
  w.u64(rng_.state());
  w.u64(moves_);
  save_state(w);
}

void Agent::load(ByteReader& r) {
  rng_.set_state(r.u64());
  moves_ = r.u64();
  load_state(r);
}

namespace {

// Uniformly random moves: the baseline every learner must beat (seed Fig. 4.6).
class RandomAgent : public Agent {
 public:
  using Agent::Agent;
  std::string name() const override { return "random"; }
  std::string network() const override { return "none, " + std::to_string(actions_) + " actions"; }
  int act(const std::vector<float>&, bool) override { return random_action(); }
  std::vector<double> q_values(const std::vector<float>&) override { return std::vector<double>(actions_, 0.0); }
  std::uint64_t parameter_count() const override { return 0; }
  void observe(const Transition&) override { ++moves_; }
  double epsilon() const override { return 1.0; }

 protected:
  void save_state(ByteWriter&) const override {}
  void load_state(ByteReader&) override {}
};

}  // namespace

std::string default_obs(const std::string& agent) { return agent == "dqn" ? "local" : "simple"; }

double default_lr(const std::string& obs) { return obs == "visual" || obs == "multimodal" ? 0.004 : 0.0025; }

std::unique_ptr<Agent> make_agent(const std::string& name, rl::ObsKind obs, const std::vector<rl::Space>& spaces,
                                  int actions, const AgentOptions& options) {
  if (name == "random") return std::make_unique<RandomAgent>(options, actions);
  if (name == "q") {
    if (obs != rl::ObsKind::Simple)
      throw std::invalid_argument("agent 'q' learns a table over the 'simple' observation, not '" +
                                  std::string(rl::obs_kind_name(obs)) + "'");
    return std::make_unique<QAgent>(options, actions);
  }
  if (name == "dqn") {
    if (obs == rl::ObsKind::Ram)
      throw std::invalid_argument("agent 'dqn' has no network for the 2 MiB 'ram' observation: use --obs local, "
                                  "visual, multimodal, episode, audio or simple");
    bool interpret = obs == rl::ObsKind::Visual || obs == rl::ObsKind::Multimodal;
    return make_dqn_agent(spaces, interpret, actions, options);
  }
  throw std::invalid_argument("unknown agent '" + name + "' (expected " + kAgentList + ")");
}

std::unique_ptr<Agent> make_agent(const std::string& name, rl::ObsKind obs, int inputs, int actions,
                                  const AgentOptions& options) {
  if (name == "dqn" && (obs == rl::ObsKind::Visual || obs == rl::ObsKind::Multimodal))
    throw std::invalid_argument("the dqn agent's " + std::string(rl::obs_kind_name(obs)) +
                                " network needs the observation's shapes, not only its length");
  rl::Space flat{"features", {inputs}, rl::DType::F32, 0, 0};
  return make_agent(name, obs, std::vector<rl::Space>{flat}, actions, options);
}

}  // namespace psxrl::agents
