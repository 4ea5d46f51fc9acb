// Deep Q-learning (seed §3.3.4, §4.2.1): the agent-local network, experience replay (§3.3.2),
// Adam + MSE towards r + gamma max Q(s'), each replay batch trained for several epochs.
#include "rl/agents/dqn_agent.h"

#include <torch/torch.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace psxrl::agents {

namespace {

// Fully connected: inputs -> 4 PReLU hidden layers -> actions, tanh (or linear) output. Five
// Linear layers, as the seed's "5 layers" network with 11 inputs and 4 outputs.
struct QNetImpl : torch::nn::Module {
  static constexpr int kHiddenLayers = 4;
  QNetImpl(int inputs, int hidden, int actions, bool linear_output) : linear_output(linear_output) {
    int in = inputs;
    for (int i = 0; i < kHiddenLayers; ++i) {
      fc.push_back(register_module("fc" + std::to_string(i), torch::nn::Linear(in, hidden)));
      act.push_back(register_module("prelu" + std::to_string(i), torch::nn::PReLU()));
      in = hidden;
    }
    out = register_module("out", torch::nn::Linear(hidden, actions));
  }
  torch::Tensor forward(torch::Tensor x) {
    for (size_t i = 0; i < fc.size(); ++i) x = act[i]->forward(fc[i]->forward(x));
    x = out->forward(x);
    return linear_output ? x : torch::tanh(x);
  }
  std::vector<torch::nn::Linear> fc;
  std::vector<torch::nn::PReLU> act;
  torch::nn::Linear out{nullptr};
  bool linear_output;
};
TORCH_MODULE(QNet);

std::string archive_bytes(const std::function<void(torch::serialize::OutputArchive&)>& save) {
  torch::serialize::OutputArchive archive;
  save(archive);
  std::ostringstream os;
  archive.save_to(os);
  return os.str();
}

void load_archive(const std::string& bytes, const std::function<void(torch::serialize::InputArchive&)>& load) {
  try {
    torch::serialize::InputArchive archive;
    std::istringstream is(bytes);
    archive.load_from(is);
    load(archive);
  } catch (const c10::Error& e) {
    throw CorruptCheckpoint(std::string("network state does not load: ") + e.what_without_backtrace());
  }
}

class DqnAgent : public Agent {
 public:
  DqnAgent(int inputs, int actions, const AgentOptions& options)
      : Agent(options, actions),
        inputs_(inputs),
        net_(inputs, options.hidden, actions, options.linear_output),
        target_(inputs, options.hidden, actions, options.linear_output),
        optimizer_(net_->parameters(), torch::optim::AdamOptions(options.lr)) {
    if (options_.double_dqn) options_.target_network = true;
    // Weights N(0, variance 1e-4) from the agent's own seed (§4.2.1), biases 0; a local
    // generator, so no process-wide torch state decides the start.
    auto gen = at::make_generator<at::CPUGeneratorImpl>(options.seed);
    torch::NoGradGuard no_grad;
    for (auto& p : net_->named_parameters()) {
      if (p.key().find("weight") == std::string::npos || p.key().find("prelu") != std::string::npos) continue;
      p.value().normal_(0.0, 0.01, gen);
    }
    for (auto& p : net_->named_parameters())
      if (p.key().find("bias") != std::string::npos) p.value().zero_();
    sync_target();
  }

  std::string name() const override { return "dqn"; }
  std::string network() const override {
    std::string s = "mlp " + std::to_string(inputs_);
    for (int i = 0; i < QNetImpl::kHiddenLayers; ++i) s += "-" + std::to_string(options_.hidden);
    return s + "-" + std::to_string(actions_) + " prelu " + (options_.linear_output ? "linear" : "tanh");
  }

  int act(const std::vector<float>& state, bool greedy) override {
    if (!greedy && explore()) return random_action();
    torch::NoGradGuard no_grad;
    return static_cast<int>(net_->forward(row(state)).argmax().item<std::int64_t>());
  }

  void observe(const Transition& t) override {
    ++moves_;
    if (memory_.size() < options_.replay_capacity) memory_.push_back(t);
    else memory_[next_] = t;
    next_ = (next_ + 1) % options_.replay_capacity;
  }

  void learn() override {
    if (memory_.empty()) return;
    std::vector<size_t> picked = sample();
    auto n = static_cast<std::int64_t>(picked.size());
    torch::Tensor s = torch::empty({n, inputs_}), s2 = torch::empty({n, inputs_});
    torch::Tensor a = torch::empty({n}, torch::kLong), r = torch::empty({n}), live = torch::empty({n});
    for (std::int64_t i = 0; i < n; ++i) {
      const Transition& t = memory_[picked[static_cast<size_t>(i)]];
      s[i] = row(t.state)[0];
      s2[i] = row(t.next_state)[0];
      a[i] = t.action;
      r[i] = static_cast<float>(t.reward);
      live[i] = t.terminal ? 0.0f : 1.0f;
    }
    torch::Tensor y = targets(s2, r, live);
    torch::Tensor taken = a.unsqueeze(1);
    for (int e = 0; e < options_.epochs; ++e) {
      optimizer_.zero_grad();
      torch::Tensor loss = torch::mse_loss(net_->forward(s).gather(1, taken).squeeze(1), y);
      loss.backward();
      optimizer_.step();
      last_loss_ = loss.item<double>();
    }
    if (options_.target_network && moves_ % options_.target_sync == 0) sync_target();
  }
  double last_loss() const override { return last_loss_; }

 protected:
  void save_state(ByteWriter& w) const override {
    w.str(archive_bytes([&](auto& ar) { net_->save(ar); }));
    w.str(archive_bytes([&](auto& ar) { target_->save(ar); }));
    w.str(archive_bytes([&](auto& ar) { optimizer_.save(ar); }));
    w.f64(last_loss_);
    w.u64(next_);
    w.u64(memory_.size());
    for (const Transition& t : memory_) {
      w.f32s(t.state);
      w.u64(static_cast<std::uint64_t>(t.action));
      w.f64(t.reward);
      w.f32s(t.next_state);
      w.u64(t.terminal);
    }
  }
  void load_state(ByteReader& r) override {
    std::string net = r.str(), target = r.str(), optimizer = r.str();
    load_archive(net, [&](auto& ar) { net_->load(ar); });
    load_archive(target, [&](auto& ar) { target_->load(ar); });
    load_archive(optimizer, [&](auto& ar) { optimizer_.load(ar); });
    last_loss_ = r.f64();
    next_ = r.u64();
    std::uint64_t n = r.count(40);
    if (n > options_.replay_capacity || next_ >= options_.replay_capacity) r.fail("replay memory larger than its capacity");
    memory_.assign(n, {});
    for (Transition& t : memory_) {
      t.state = r.f32s();
      t.action = static_cast<int>(r.u64());
      t.reward = r.f64();
      t.next_state = r.f32s();
      t.terminal = r.u64() != 0;
      if (t.state.size() != static_cast<size_t>(inputs_) || t.next_state.size() != t.state.size() || t.action < 0 ||
          t.action >= actions_)
        r.fail("a replay entry that does not fit the network");
    }
  }

 private:
  torch::Tensor row(const std::vector<float>& state) const {
    if (state.size() != static_cast<size_t>(inputs_))
      throw std::invalid_argument("dqn: observation has " + std::to_string(state.size()) + " values, the network " +
                                  std::to_string(inputs_));
    return torch::from_blob(const_cast<float*>(state.data()), {1, inputs_}, torch::kFloat32).clone();
  }

  // Up to `batch` distinct entries, uniformly (rejection is cheap: batch << capacity).
  std::vector<size_t> sample() {
    size_t n = std::min(options_.batch, memory_.size());
    std::vector<size_t> picked;
    if (n == memory_.size()) {
      for (size_t i = 0; i < n; ++i) picked.push_back(i);
      return picked;
    }
    while (picked.size() < n) {
      size_t i = rng_.below(memory_.size());
      if (std::find(picked.begin(), picked.end(), i) == picked.end()) picked.push_back(i);
    }
    return picked;
  }

  // r + gamma max_a' Q(s', a') (Eq. 3.3), fixed for the batch's epochs; with a target network
  // Q(s') comes from it, and Double DQN picks a' with the online network.
  torch::Tensor targets(const torch::Tensor& s2, const torch::Tensor& r, const torch::Tensor& live) {
    torch::NoGradGuard no_grad;
    QNet& evaluator = options_.target_network ? target_ : net_;
    torch::Tensor next = evaluator->forward(s2), best;
    if (options_.double_dqn) best = next.gather(1, net_->forward(s2).argmax(1, true)).squeeze(1);
    else best = std::get<0>(next.max(1));
    return r + static_cast<float>(options_.gamma) * live * best;
  }

  void sync_target() {
    torch::NoGradGuard no_grad;
    auto from = net_->parameters(), to = target_->parameters();
    for (size_t i = 0; i < from.size(); ++i) to[i].copy_(from[i]);
  }

  std::int64_t inputs_;
  QNet net_, target_;
  torch::optim::Adam optimizer_;
  std::vector<Transition> memory_;
  size_t next_ = 0;
  double last_loss_ = 0;
};

}  // namespace

std::unique_ptr<Agent> make_dqn_agent(int inputs, int actions, const AgentOptions& options) {
  // One intra-op thread: the same seed gives the same floating-point sums, and the emulator keeps
  // the other cores.
  torch::set_num_threads(1);
  return std::make_unique<DqnAgent>(inputs, actions, options);
}

}  // namespace psxrl::agents
