// Deep Q-learning (seed §3.3.4, §3.3.5, §4.2.1): the agent-local or multimodal network
// (q_networks.h), experience replay (§3.3.2), Adam + MSE towards r + gamma max Q(s'), each replay
// batch trained for several epochs.
#include "rl/agents/dqn_agent.h"

#include "rl/agents/q_networks.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace psxrl::agents {

namespace {

// A state as the replay memory keeps it: the byte arrays (frames) as bytes, the rest as floats,
// so a visual state takes a quarter of the memory.
struct Packed {
  std::vector<float> f32;
  std::vector<std::uint8_t> u8;
};

struct Stored {
  Packed state, next_state;
  int action = 0;
  double reward = 0;
  bool terminal = false;
};

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

std::vector<Slice> slices_of(const std::vector<rl::Space>& spaces) {
  std::vector<Slice> out;
  std::int64_t offset = 0;
  for (const rl::Space& s : spaces) {
    auto n = static_cast<std::int64_t>(s.elements());
    out.push_back({s, offset, n});
    offset += n;
  }
  return out;
}

class DqnAgent : public Agent {
 public:
  DqnAgent(const std::vector<rl::Space>& spaces, bool interpret, int actions, const AgentOptions& options)
      : Agent(options, actions),
        slices_(slices_of(spaces)),
        net_(slices_, interpret, options.hidden, actions, options.linear_output),
        target_(slices_, interpret, options.hidden, actions, options.linear_output),
        optimizer_(net_->parameters(), torch::optim::AdamOptions(options.lr)) {
    for (const Slice& s : slices_) {
      inputs_ += s.size;
      (s.space.dtype == rl::DType::U8 ? u8_size_ : f32_size_) += static_cast<size_t>(s.size);
    }
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
    std::string s;
    if (net_->interpret) {
      s = "interpretive";
      for (const Slice& sl : slices_) {
        s += " " + sl.space.name + "[";
        for (size_t i = 0; i < sl.space.shape.size(); ++i) s += (i ? "x" : "") + std::to_string(sl.space.shape[i]);
        s += "]";
      }
    }
    s += (s.empty() ? "mlp " : " -> mlp ") + std::to_string(net_->head_inputs);
    for (int i = 0; i < QNetImpl::kHiddenLayers; ++i) s += "-" + std::to_string(options_.hidden);
    return s + "-" + std::to_string(actions_) + " prelu " + (options_.linear_output ? "linear" : "tanh");
  }
  std::uint64_t parameter_count() const override {
    std::uint64_t n = 0;
    for (const auto& p : net_->parameters()) n += static_cast<std::uint64_t>(p.numel());
    return n;
  }

  std::vector<double> q_values(const std::vector<float>& state) override {
    torch::NoGradGuard no_grad;
    torch::Tensor q = net_->forward(row(state))[0].to(torch::kDouble).contiguous();
    return std::vector<double>(q.data_ptr<double>(), q.data_ptr<double>() + q.numel());
  }

  int act(const std::vector<float>& state, bool greedy) override {
    if (!greedy && explore()) return exploratory_action(state);
    torch::NoGradGuard no_grad;
    return static_cast<int>(net_->forward(row(state)).argmax().item<std::int64_t>());
  }

  void observe(const Transition& t) override {
    ++moves_;
    Stored s{pack(t.state), pack(t.next_state), t.action, t.reward, t.terminal};
    if (memory_.size() < options_.replay_capacity) memory_.push_back(std::move(s));
    else memory_[next_] = std::move(s);
    next_ = (next_ + 1) % options_.replay_capacity;
  }

  void learn() override {
    if (memory_.empty()) return;
    std::vector<size_t> picked = sample();
    auto n = static_cast<std::int64_t>(picked.size());
    torch::Tensor s = torch::empty({n, inputs_}), s2 = torch::empty({n, inputs_});
    torch::Tensor a = torch::empty({n}, torch::kLong), r = torch::empty({n}), live = torch::empty({n});
    // Filled through their data pointers: an indexed assignment (a[i] = ...) is two tensor
    // operations, 480 a batch, about a fifth of the learner's per-move cost (docs/results.md).
    std::int64_t* action = a.data_ptr<std::int64_t>();
    float *reward = r.data_ptr<float>(), *alive = live.data_ptr<float>();
    for (std::int64_t i = 0; i < n; ++i) {
      const Stored& t = memory_[picked[static_cast<size_t>(i)]];
      unpack(t.state, s.data_ptr<float>() + i * inputs_);
      unpack(t.next_state, s2.data_ptr<float>() + i * inputs_);
      action[i] = t.action;
      reward[i] = static_cast<float>(t.reward);
      alive[i] = t.terminal ? 0.0f : 1.0f;
    }
    torch::Tensor y = targets(s2, r, live);
    torch::Tensor taken = a.unsqueeze(1);
    for (int e = 0; e < options_.epochs; ++e) {
      optimizer_.zero_grad();
      torch::Tensor loss = torch::mse_loss(net_->forward(s).gather(1, taken).squeeze(1), y);
      loss.backward();
      optimizer_.step();
      last_loss_ = loss.item<double>();
      ++updates_;
    }
    if (options_.target_network && moves_ % options_.target_sync == 0) sync_target();
  }
  double last_loss() const override { return last_loss_; }

 protected:
  // Replay entries: floats (as f64), then, when the observation has byte arrays, their bytes; an
  // all-float observation keeps the layout of the first checkpoint format.
  void save_state(ByteWriter& w) const override {
    w.str(archive_bytes([&](auto& ar) { net_->save(ar); }));
    w.str(archive_bytes([&](auto& ar) { target_->save(ar); }));
    w.str(archive_bytes([&](auto& ar) { optimizer_.save(ar); }));
    w.f64(last_loss_);
    w.u64(next_);
    w.u64(memory_.size());
    for (const Stored& t : memory_) {
      save_packed(w, t.state);
      w.u64(static_cast<std::uint64_t>(t.action));
      w.f64(t.reward);
      save_packed(w, t.next_state);
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
    for (Stored& t : memory_) {
      t.state = load_packed(r);
      t.action = static_cast<int>(r.u64());
      t.reward = r.f64();
      t.next_state = load_packed(r);
      t.terminal = r.u64() != 0;
      if (t.action < 0 || t.action >= actions_) r.fail("a replay entry with an action the network does not have");
    }
  }

 private:
  torch::Tensor row(const std::vector<float>& state) const {
    if (state.size() != static_cast<size_t>(inputs_))
      throw std::invalid_argument("dqn: observation has " + std::to_string(state.size()) + " values, the network " +
                                  std::to_string(inputs_));
    return torch::from_blob(const_cast<float*>(state.data()), {1, inputs_}, torch::kFloat32).clone();
  }

  Packed pack(const std::vector<float>& state) const {
    if (state.size() != static_cast<size_t>(inputs_))
      throw std::invalid_argument("dqn: a transition's state has " + std::to_string(state.size()) +
                                  " values, the network " + std::to_string(inputs_));
    Packed p;
    p.f32.reserve(f32_size_);
    p.u8.reserve(u8_size_);
    for (const Slice& s : slices_) {
      const float* v = state.data() + s.offset;
      if (s.space.dtype == rl::DType::U8) {
        for (std::int64_t i = 0; i < s.size; ++i) p.u8.push_back(static_cast<std::uint8_t>(v[i]));
      } else {
        p.f32.insert(p.f32.end(), v, v + s.size);
      }
    }
    return p;
  }
  void unpack(const Packed& p, float* out) const {
    size_t f = 0, b = 0;
    for (const Slice& s : slices_) {
      float* o = out + s.offset;
      for (std::int64_t i = 0; i < s.size; ++i)
        o[i] = s.space.dtype == rl::DType::U8 ? static_cast<float>(p.u8[b++]) : p.f32[f++];
    }
  }
  void save_packed(ByteWriter& w, const Packed& p) const {
    w.f32s(p.f32);
    if (u8_size_) w.u8s(p.u8);
  }
  Packed load_packed(ByteReader& r) const {
    Packed p;
    p.f32 = r.f32s();
    if (u8_size_) p.u8 = r.u8s();
    if (p.f32.size() != f32_size_ || p.u8.size() != u8_size_) r.fail("a replay entry that does not fit the network");
    return p;
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

  std::vector<Slice> slices_;
  std::int64_t inputs_ = 0;
  size_t f32_size_ = 0, u8_size_ = 0;
  QNet net_, target_;
  torch::optim::Adam optimizer_;
  std::vector<Stored> memory_;
  size_t next_ = 0;
  double last_loss_ = 0;
};

}  // namespace

}  // namespace psxrl::agents

// The plugin's entry points (dqn_agent.h). C linkage keeps their names plain for dlsym.
extern "C" const psxrl::agents::DqnPluginStamp* psxrl_dqn_stamp() {
  static constexpr psxrl::agents::DqnPluginStamp kStamp = psxrl::agents::dqn_plugin_stamp();
  return &kStamp;
}

extern "C" psxrl::agents::Agent* psxrl_dqn_make_agent(const std::vector<psxrl::rl::Space>& spaces, bool interpret,
                                                      int actions, const psxrl::agents::AgentOptions& options) {
  // One intra-op thread: the same seed gives the same floating-point sums, and the emulator keeps
  // the other cores.
  torch::set_num_threads(1);
  return new psxrl::agents::DqnAgent(spaces, interpret, actions, options);
}
