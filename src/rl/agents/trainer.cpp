// The training loop, run folder and resumption (see trainer.h).
#include "rl/agents/trainer.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/atomic_file.h"
#include "rl/agents/learning_curve.h"
#include "rl/vec_env.h"

namespace psxrl::agents {

namespace fs = std::filesystem;

namespace {

std::string flag(bool b) { return b ? "true" : "false"; }

// Settings added after the first checkpoints, with the value every run before them had: an older
// checkpoint without them still resumes and plays.
const Settings kLaterSettings = {{"envs", "1"},         {"exploration", "epsilon"}, {"start_states", "0"},
                                  {"start", "level"}, {"test_starts", "none"}};

std::string setting(const Settings& s, const std::string& key) {
  auto it = s.find(key);
  if (it != s.end()) return it->second;
  auto later = kLaterSettings.find(key);
  return later == kLaterSettings.end() ? "(none)" : later->second;
}

// `start` is "level" (the run's start: the level's own, or --start's), "saved" for a --start-states
// episode, "heldout-N" for a held-out test from the N-th --test-start (kind "heldout").
const char* kCsvHeader = "episode,kind,score,reward,moves,frames,outcome,epsilon,loss,total_moves,seconds,start\n";

std::string start_name(const EpisodeRecord& r) {
  return r.heldout ? "heldout-" + std::to_string(r.heldout) : r.saved_start ? "saved" : "level";
}

const char* kind_name(const EpisodeRecord& r) { return r.heldout ? "heldout" : r.test ? "test" : "train"; }

std::string csv_row(const EpisodeRecord& r) {
  return std::to_string(r.episode) + "," + kind_name(r) + "," + std::to_string(r.score) + "," +
         format_double(r.reward) + "," + std::to_string(r.moves) + "," + std::to_string(r.frames) + "," + r.outcome +
         "," + format_double(r.epsilon) + "," + format_double(r.loss) + "," + std::to_string(r.total_moves) + "," +
         format_double(r.seconds) + "," + start_name(r) + "\n";
}

std::string json_row(const EpisodeRecord& r) {
  return "{\"episode\":" + std::to_string(r.episode) + ",\"kind\":\"" + kind_name(r) +
         "\",\"score\":" + std::to_string(r.score) + ",\"reward\":" + format_double(r.reward) +
         ",\"moves\":" + std::to_string(r.moves) + ",\"frames\":" + std::to_string(r.frames) + ",\"outcome\":\"" +
         r.outcome + "\",\"epsilon\":" + format_double(r.epsilon) + ",\"loss\":" + format_double(r.loss) +
         ",\"total_moves\":" + std::to_string(r.total_moves) + ",\"seconds\":" + format_double(r.seconds) +
         ",\"start\":\"" + start_name(r) + "\"}\n";
}

void write_text_atomically(const std::string& path, const std::string& text) {
  psx::write_file_atomically(path, std::vector<psx::u8>(text.begin(), text.end()));
}

void save_record(ByteWriter& w, const EpisodeRecord& r) {
  w.u64(r.episode);
  w.u64(r.test);
  w.i64(r.score);
  w.f64(r.reward);
  w.u64(r.moves);
  w.u64(r.frames);
  w.str(r.outcome);
  w.f64(r.epsilon);
  w.f64(r.loss);
  w.u64(r.total_moves);
  w.f64(r.seconds);
}

EpisodeRecord load_record(ByteReader& r) {
  EpisodeRecord e;
  e.episode = r.u64();
  e.test = r.u64() != 0;
  e.score = r.i64();
  e.reward = r.f64();
  e.moves = static_cast<std::uint32_t>(r.u64());
  e.frames = r.u64();
  e.outcome = r.str();
  e.epsilon = r.f64();
  e.loss = r.f64();
  e.total_moves = r.u64();
  e.seconds = r.f64();
  return e;
}

std::string test_starts_setting(const std::vector<std::string>& starts) {
  std::string s;
  for (const std::string& t : starts) s += (s.empty() ? "" : ";") + t;
  return starts.empty() ? "none" : s;
}

}  // namespace

Settings run_settings(const TrainConfig& c) {
  const AgentOptions& o = c.options;
  return {{"game", c.env.game},
          {"level", std::to_string(c.level)},
          {"agent", c.agent},
          {"obs", c.env.obs},
          {"visual_gray", flag(c.env.visual_gray)},
          {"reward", c.env.reward},
          {"gamma", format_double(c.env.gamma)},
          {"seed", std::to_string(c.seed)},
          {"max_moves", c.env.max_moves ? std::to_string(*c.env.max_moves) : "game"},
          {"test_every", std::to_string(c.test_every)},
          {"envs", std::to_string(c.envs)},
          {"start_states", format_double(c.start_states)},
          {"start", c.start.empty() ? "level" : c.start},
          {"test_starts", test_starts_setting(c.test_starts)},
          {"alpha", format_double(o.alpha)},
          {"lr", format_double(o.lr)},
          {"hidden", std::to_string(o.hidden)},
          {"replay", std::to_string(o.replay_capacity)},
          {"batch", std::to_string(o.batch)},
          {"epochs", std::to_string(o.epochs)},
          {"epsilon_start", format_double(o.epsilon_start)},
          {"epsilon_end", format_double(o.epsilon_end)},
          {"epsilon_moves", std::to_string(o.epsilon_moves)},
          {"linear_output", flag(o.linear_output)},
          // --double-dqn bootstraps from a target network whether or not --target-network was given
          {"target_network", flag(o.target_network || o.double_dqn)},
          {"target_sync", std::to_string(o.target_sync)},
          {"double_dqn", flag(o.double_dqn)},
          {"exploration", exploration_name(o.exploration)}};
}

void apply_settings(const Settings& s, TrainConfig& c) {
  auto get = [&](const char* k) {
    std::string v = setting(s, k);
    if (v == "(none)") throw CorruptCheckpoint(std::string("checkpoint settings lack '") + k + "'");
    return v;
  };
  try {
    c.env.game = get("game");
    c.level = std::stoi(get("level"));
    c.agent = get("agent");
    c.env.obs = get("obs");
    c.env.visual_gray = get("visual_gray") == "true";
    c.env.reward = get("reward");
    c.env.gamma = std::stod(get("gamma"));
    c.seed = std::stoull(get("seed"));
    if (get("max_moves") != "game") c.env.max_moves = static_cast<std::uint32_t>(std::stoul(get("max_moves")));
    c.test_every = std::stoi(get("test_every"));
    c.envs = std::stoi(get("envs"));
    c.start_states = std::stod(get("start_states"));
    c.start = get("start") == "level" ? "" : get("start");
    c.test_starts.clear();
    std::istringstream starts(get("test_starts"));
    for (std::string t; std::getline(starts, t, ';');)
      if (t != "none") c.test_starts.push_back(t);
    AgentOptions& o = c.options;
    o.alpha = std::stod(get("alpha"));
    o.lr = std::stod(get("lr"));
    o.hidden = std::stoi(get("hidden"));
    o.replay_capacity = std::stoull(get("replay"));
    o.batch = std::stoull(get("batch"));
    o.epochs = std::stoi(get("epochs"));
    o.epsilon_start = std::stod(get("epsilon_start"));
    o.epsilon_end = std::stod(get("epsilon_end"));
    o.epsilon_moves = std::stoull(get("epsilon_moves"));
    o.linear_output = get("linear_output") == "true";
    o.target_network = get("target_network") == "true";
    o.target_sync = std::stoull(get("target_sync"));
    o.double_dqn = get("double_dqn") == "true";
    o.exploration = parse_exploration(get("exploration"));
  } catch (const std::logic_error& e) {  // stoi and friends on a damaged value, an unknown name
    throw CorruptCheckpoint(std::string("checkpoint settings hold a value psxrl cannot read: ") + e.what());
  }
  c.options.gamma = c.env.gamma;
  c.options.seed = c.seed;
}

// The saved-state generator: its own stream, so runs without --start-states draw nothing new.
Trainer::Trainer(const TrainConfig& config) : config_(config), start_rng_(rl::episode_seed(config.seed, -1, 0)) {
  config_.options.gamma = config_.env.gamma;
  config_.options.seed = config_.seed;
  if (config_.test_every < 1) throw std::invalid_argument("--test-every must be at least 1");
  if (config_.envs < 1 || config_.envs > kMaxEnvs)
    throw std::invalid_argument("--envs must be 1 to " + std::to_string(kMaxEnvs) + ", not " + std::to_string(config_.envs));
  if (config_.resume && config_.envs > 1)
    throw std::invalid_argument("--resume needs --envs 1: a checkpoint of a run with " + std::to_string(config_.envs) +
                                " environments does not hold the episodes still running in the others, so the run "
                                "could not continue exactly");
  if (!(config_.start_states >= 0 && config_.start_states <= 1))
    throw std::invalid_argument("--start-states is a probability, 0 to 1, not " + format_double(config_.start_states));
  if (config_.resume && config_.start_states > 0)
    throw std::invalid_argument("--resume needs --start-states 0: the saved states are kept in memory, not in the "
                                "checkpoint, so the run could not continue exactly");
  slots_.resize(static_cast<size_t>(config_.envs));
  // Booting is the slow part: the environments boot in parallel, as the vector environment's do.
  unsigned threads = std::max(1u, std::min(std::thread::hardware_concurrency(), static_cast<unsigned>(config_.envs)));
  pool_ = std::make_unique<rl::ThreadPool>(threads);
  pool_->parallel_for(slots_.size(), [&](size_t i) { slots_[i].env = std::make_unique<rl::Env>(config_.env); });
  const rl::Env& env = *slots_[0].env;
  if (config_.level < 1 || config_.level > env.game().level_count)
    throw std::invalid_argument("game '" + config_.env.game + "' has levels 1 to " +
                                std::to_string(env.game().level_count) + ", not " + std::to_string(config_.level));
  bool needs_position = env.obs_kind() == rl::ObsKind::Simple || env.obs_kind() == rl::ObsKind::Local;
  bool walks = !config_.start.empty() || !config_.test_starts.empty();
  if ((config_.start_states > 0 || walks) && needs_position && env.game().position_x.empty())
    throw std::invalid_argument("game '" + config_.env.game + "' follows the ball's position in its script, which a " +
                                "saved state does not hold: --start-states, --start and --test-start need an "
                                "observation without the position (visual, multimodal, episode, audio)");
  check_start_positions();
  agent_ = make_agent(config_.agent, env.obs_kind(), env.observation_spaces(), env.action_count(), config_.options);
  meta_ = run_settings(config_);
  meta_["format"] = std::to_string(kCheckpointFormat);
  meta_["psxrl_version"] = kPsxrlVersion;
  meta_["integration_hash"] = integration_hash(env.game());
  meta_["network"] = agent_->network();

  std::error_code ec;
  fs::create_directories(config_.out, ec);
  if (ec || !fs::is_directory(config_.out))
    throw std::runtime_error(config_.out + ": cannot create the run folder (" + ec.message() + ")");
  if (config_.resume) {
    restore();
    return;
  }
  if (fs::exists(file(kCheckpointFile)))
    throw std::invalid_argument(config_.out + " already holds a run: pass --resume to continue it, or choose another --out");
  std::string json = "{";
  for (const auto& [k, v] : meta_) json += (json.size() > 1 ? ",\n \"" : "\n \"") + k + "\": \"" + v + "\"";
  write_text_atomically(file("config.json"), json + "\n}\n");
  write_metrics_from_records();
}

Trainer::~Trainer() = default;

std::string Trainer::file(const char* name) const { return (fs::path(config_.out) / name).string(); }

// Parses --start and --test-start and walks each once (seed 0), so that a walk that scores or
// ends the episode is refused before the run folder is made.
void Trainer::check_start_positions() {
  if (!config_.test_starts.empty() && (config_.envs > 1 || config_.resume))
    throw std::invalid_argument("--test-start needs --envs 1 and no --resume: the held-out tests follow each test of "
                                "the one environment, and the checkpoint does not hold them");
  rl::Env& env = *slots_[0].env;
  start_ = parse_start_position(config_.start, env.actions());
  for (const std::string& t : config_.test_starts) {
    if (t.empty()) throw std::invalid_argument("--test-start needs a walk (the level's own start is --start's default)");
    test_starts_.push_back(parse_start_position(t, env.actions()));
  }
  if (!start_.moves.empty()) begin_at(env, config_.level, start_, 0, nullptr);
  for (const StartPosition& p : test_starts_) begin_at(env, config_.level, p, 0, nullptr);
}

void Trainer::restore() {
  Checkpoint c = read_checkpoint(file(kCheckpointFile));
  // Checkpoints from before config.json recorded --double-dqn's own target network.
  if (setting(c.meta, "double_dqn") == "true") c.meta["target_network"] = "true";
  for (const auto& [k, v] : meta_) {
    std::string had = setting(c.meta, k);
    if (had != v)
      throw std::invalid_argument(config_.out + " was trained with " + k + " = " + had + ", this command has " + k +
                                  " = " + v + ": resume with the run's own settings");
  }
  ByteReader agent(c.agent, file(kCheckpointFile) + " (agent)");
  agent_->load(agent);
  if (!agent.done()) agent.fail("unexpected bytes after the agent state");
  ByteReader t(c.trainer, file(kCheckpointFile) + " (trainer)");
  std::uint64_t n = t.count(80);
  for (std::uint64_t i = 0; i < n; ++i) records_.push_back(load_record(t));
  if (!t.done()) t.fail("unexpected bytes after the metrics");
  slots_[0].episodes = records_.size();  // one environment played them all
  counted_ = records_.size();            // a resumed run has no held-out tests
  write_metrics_from_records();
}

void Trainer::save(bool curve) const {
  Checkpoint c;
  c.meta = meta_;
  ByteWriter agent, trainer;
  agent_->save(agent);
  trainer.u64(records_.size());
  for (const EpisodeRecord& r : records_) save_record(trainer, r);
  c.agent = agent.take_string();
  c.trainer = trainer.take_string();
  write_checkpoint(file(kCheckpointFile), c);
  if (curve) write_learning_curve(file("learning_curve.png"), records_);
}

// The metric files always match the checkpoint's records: a resumed run drops rows written after
// its checkpoint.
void Trainer::write_metrics_from_records() const {
  std::string csv = kCsvHeader, jsonl;
  for (const EpisodeRecord& r : records_) {
    csv += csv_row(r);
    jsonl += json_row(r);
  }
  write_text_atomically(file("metrics.csv"), csv);
  write_text_atomically(file("metrics.jsonl"), jsonl);
}

void Trainer::append_metrics(const EpisodeRecord& r) const {
  std::ofstream(file("metrics.csv"), std::ios::app) << csv_row(r);
  std::ofstream(file("metrics.jsonl"), std::ios::app) << json_row(r);
}

}  // namespace psxrl::agents
