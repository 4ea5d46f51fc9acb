// Tabular Q-learning (seed §3.3.3), declared here so tests can read the table.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "rl/agents/agent.h"

namespace psxrl::agents {

// Tabular Q-learning on the simple state index. The table is sparse, as the seed's dictionary:
// positions the ball never reaches take no memory.
class QAgent : public Agent {
 public:
  using Agent::Agent;
  std::string name() const override { return "q"; }
  std::string network() const override { return "q-table over the simple index, " + std::to_string(actions_) + " actions"; }

  int act(const std::vector<float>& state, bool greedy) override {
    if (!greedy && explore()) return exploratory_action(state);
    const std::vector<double>* q = find(key(state));
    if (!q) return 0;  // every value is 0: the first action is the first best
    return static_cast<int>(std::max_element(q->begin(), q->end()) - q->begin());
  }

  std::vector<double> q_values(const std::vector<float>& state) override {
    const std::vector<double>* q = find(key(state));
    return q ? *q : std::vector<double>(static_cast<size_t>(actions_), 0.0);
  }
  std::uint64_t parameter_count() const override { return table_.size() * static_cast<std::uint64_t>(actions_); }

  // Q(s,a) <- (1 - alpha) Q(s,a) + alpha (r + gamma max_a' Q(s',a')), no future past a win or loss.
  void observe(const Transition& t) override {
    ++moves_;
    double future = 0;
    if (!t.terminal) {
      if (const std::vector<double>* next = find(key(t.next_state))) future = *std::max_element(next->begin(), next->end());
    }
    double& q = row(key(t.state))[static_cast<size_t>(t.action)];
    q = (1 - options_.alpha) * q + options_.alpha * (t.reward + options_.gamma * future);
    ++updates_;
  }

  double value(std::int64_t state, int action) const {
    const std::vector<double>* q = find(state);
    return q ? (*q)[static_cast<size_t>(action)] : 0.0;
  }

 protected:
  void save_state(ByteWriter& w) const override {
    std::map<std::int64_t, std::vector<double>> sorted(table_.begin(), table_.end());  // a stable byte order
    w.u64(sorted.size());
    for (const auto& [s, q] : sorted) {
      w.i64(s);
      for (double v : q) w.f64(v);
    }
  }
  void load_state(ByteReader& r) override {
    table_.clear();
    std::uint64_t n = r.count(8 * (1 + static_cast<size_t>(actions_)));
    for (std::uint64_t i = 0; i < n; ++i) {
      std::vector<double>& q = row(r.i64());
      for (double& v : q) v = r.f64();
    }
  }

 private:
  static std::int64_t key(const std::vector<float>& state) { return std::llround(state.at(0)); }
  const std::vector<double>* find(std::int64_t s) const {
    auto it = table_.find(s);
    return it == table_.end() ? nullptr : &it->second;
  }
  std::vector<double>& row(std::int64_t s) {
    auto [it, fresh] = table_.try_emplace(s);
    if (fresh) it->second.assign(static_cast<size_t>(actions_), 0.0);
    return it->second;
  }
  std::unordered_map<std::int64_t, std::vector<double>> table_;
};

}  // namespace psxrl::agents
