// The environment (see env.h): boot and level start, moves, rewards, outcome, observations.
#include "rl/env.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/console.h"
#include "core/sha1.h"
#include "lua/lua_host.h"

#ifndef PSXRL_GAMES_DIR
#error "PSXRL_GAMES_DIR must name the source tree's games folder"
#endif

namespace psxrl::rl {

std::string default_games_dir() {
  if (const char* env = std::getenv("PSXRL_GAMES")) return env;
  return PSXRL_GAMES_DIR;
}

std::string default_build_games_dir() { return PSXRL_BUILD_GAMES_DIR; }

RewardKind parse_reward_kind(const std::string& name) {
  if (name == "table") return RewardKind::Table;
  if (name == "score") return RewardKind::Score;
  if (name == "script") return RewardKind::Script;
  throw std::invalid_argument("unknown reward '" + name + "' (expected table, score or script)");
}

namespace {

// splitmix64: the environment's own generator; its whole state is one word seeded by reset().
std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

Env::Env(const EnvConfig& config) : config_(config) {
  if (config_.games_dir.empty()) config_.games_dir = default_games_dir();
  if (config_.build_games_dir.empty()) config_.build_games_dir = default_build_games_dir();
  obs_kind_ = parse_obs_kind(config_.obs);
  reward_kind_ = parse_reward_kind(config_.reward);
  if (!(config_.gamma >= 0 && config_.gamma < 1)) throw std::invalid_argument("gamma must be in [0, 1)");
  game_ = load_integration(config_.games_dir, config_.game, config_.build_games_dir);
  delim_ = {config_.initial_delay.value_or(game_.initial_delay), config_.delay.value_or(game_.delay),
            config_.max_move_frames.value_or(game_.max_move_frames)};
  max_moves_ = config_.max_moves.value_or(game_.max_moves);
  sticky_ = config_.sticky.value_or(game_.sticky);
  game_.watch_audio = config_.watch_audio.value_or(game_.watch_audio);
  maps_.resize(static_cast<size_t>(game_.level_count) + 1);
  lua_ = std::make_unique<lua::Host>(game_.folder);
  bind_script();
  if (!game_.script.empty()) lua_->run_file(game_.script);
  // Looked up once: the move loop reads these every emulated frame.
  for (const auto& w : game_.watch) watched_vars_.push_back(&game_.variable(w));
  state_var_ = &game_.variable(game_.state_variable);
  script_outcome_ = lua_->has_function("outcome");
  if (reward_kind_ == RewardKind::Script && !lua_->has_function("reward"))
    throw psx::InputError::whole(game_.manifest, "reward 'script' needs a reward() function in the script");
  bool positional = obs_kind_ == ObsKind::Simple || obs_kind_ == ObsKind::Local;
  if (positional && game_.map_pattern.empty())
    throw std::invalid_argument("game '" + game_.name + "' has no level maps, so no '" + config_.obs + "' observation");
  if (positional && game_.position_x.empty() && !lua_->has_function("position"))
    throw psx::InputError::whole(game_.manifest, "[observations.position] or a position() function is needed for '" +
                                                     config_.obs + "'");
  console_ = std::make_unique<psx::Console>();
  if (config_.cpu == "recompiler") console_->set_cpu_mode(psx::Console::CpuMode::Recompiler);
  else if (config_.cpu != "interpreter")
    throw std::invalid_argument("cpu: 'interpreter' or 'recompiler', not '" + config_.cpu + "'");
  use_renderer();
  // Pictures are drawn only when asked for: a visual observation asks for the frame at the end
  // of a step, so the frames before it are drawn only where they show through (their drawing is
  // kept and replayed exactly, gpu/draw_queue.h). Frame requests for a window or a video still
  // get every frame, exactly.
  console_->set_pixels_observed(false);
  // Likewise sound is mixed only when something hears it (re-checked each step for on_frame).
  listen();
  boot();

  auto space = [&](std::string name, std::vector<std::int64_t> shape, DType d, double lo, double hi) {
    spaces_.push_back({std::move(name), std::move(shape), d, lo, hi});
  };
  int local_cells = (game_.local_ahead + game_.local_behind + 1) * (2 * game_.local_side + 1);
  int planes = config_.visual_gray ? 1 : 3;
  switch (obs_kind_) {
    case ObsKind::Simple: space("simple", {1}, DType::I64, 0, 4.0 * LevelMap::kMaxSize * LevelMap::kMaxSize - 1); break;
    case ObsKind::Local: space("local", {local_cells + 2}, DType::F32, -1e9, 1e9); break;
    case ObsKind::Episode: space("episode", {3}, DType::F32, -1e9, 1e9); break;
    case ObsKind::Ram: space("ram", {2 * 1024 * 1024}, DType::U8, 0, 255); break;
    case ObsKind::Rumble: space("rumble", {2}, DType::U8, 0, 255); break;
    case ObsKind::Audio: space("audio", {game_.audio_frames, kMfccCoefficients}, DType::F32, -1e9, 1e9); break;
    case ObsKind::Multimodal:
    case ObsKind::Visual:
      space("visual", {planes, game_.visual_out_h, game_.visual_out_w}, DType::U8, 0, 255);
      if (obs_kind_ == ObsKind::Visual) break;
      space("episode", {3}, DType::F32, -1e9, 1e9);
      space("audio", {game_.audio_frames, kMfccCoefficients}, DType::F32, -1e9, 1e9);
      break;
  }
  simple_buf_.resize(1);
  local_buf_.resize(static_cast<size_t>(local_cells) + 2);
  episode_buf_.resize(3);
  audio_buf_.resize(static_cast<size_t>(game_.audio_frames) * kMfccCoefficients);
  visual_buf_.resize(static_cast<size_t>(planes) * game_.visual_out_w * game_.visual_out_h);
  rumble_buf_.resize(2);
}

Env::~Env() = default;

// The configured renderer; an unknown name or scale is std::invalid_argument, OpenGL missing a
// std::runtime_error.
void Env::use_renderer() {
  if (config_.renderer == "software" && config_.scale == 1) return;
  if (config_.renderer != "software" && config_.renderer != "gl")
    throw std::invalid_argument("renderer: 'software' or 'gl', not '" + config_.renderer + "'");
  if (config_.scale < 1 || config_.scale > psx::Console::kMaxRenderScale)
    throw std::invalid_argument("scale: 1 to 8, not " + std::to_string(config_.scale));
  if (config_.renderer == "software") throw std::invalid_argument("scale: the software renderer draws at 1; use 'gl'");
  std::string error;
  if (!console_->use_gl_renderer(config_.scale, error))
    throw std::runtime_error("renderer 'gl': OpenGL is not available: " + error);
}

void Env::boot() {
  if (game_.needs_bios) {
    if (config_.files.bios.empty())
      throw psx::InputError("game '" + game_.name + "' needs your PlayStation BIOS image: pass --bios FILE (see " +
                            game_.folder + "/README.md)");
    console_->load_bios(config_.files.bios);
  }
  if (!game_.exe.empty()) {
    console_->boot_exe(game_.exe);
  } else {
    std::string disc = game_.user_disc ? config_.files.disc : game_.disc;
    if (disc.empty())
      throw psx::InputError("game '" + game_.name + "' needs your own disc image: pass --disc FILE.cue (see " +
                            game_.folder + "/README.md)");
    console_->insert_disc(disc);
    if (game_.user_disc) check_disc_identity(disc);
    console_->boot_disc();
  }
  if (!game_.boot_ready.variable.empty()) {
    const Variable& v = game_.variable(game_.boot_ready.variable);
    bool ready = console_->run_until([&] { return contains_value(game_.boot_ready.values, raw(v)); }, game_.boot_max_frames);
    if (!ready)
      throw psx::InputError::whole(game_.manifest, "[boot] ready: " + v.name + " did not reach a ready value within " +
                                                       std::to_string(game_.boot_max_frames) + " frames" +
                                                       (console_->fatal_error().empty() ? "" : ": " + console_->fatal_error()));
  }
  console_->snapshot(boot_state_);
}

// A user's disc is the game the integration was written for when the SHA-1 of its first data
// track (raw 2352-byte sectors from INDEX 01 to the track's end) is one the manifest lists.
void Env::check_disc_identity(const std::string& path) {
  if (game_.disc_sha1.empty()) return;
  psx::disc::Disc& disc = *console_->cdrom().disc();
  for (const auto& track : disc.tracks()) {
    if (track.type == psx::disc::TrackType::Audio) continue;
    psx::Sha1 sha;
    psx::disc::RawSector sector;
    for (psx::u32 s = track.index1; s < track.end; ++s) {
      if (!disc.read_sector(s, sector)) throw psx::InputError::whole(path, "cannot read the data track: " + disc.last_error());
      sha.update(sector.data(), sector.size());
    }
    std::string found = sha.hex();
    if (contains_string(game_.disc_sha1, found)) return;
    std::string known;
    for (const auto& k : game_.disc_sha1) known += (known.empty() ? "" : ", ") + k;
    throw psx::InputError::whole(path, "this is not a disc " + game_.manifest + " knows: its data track's SHA-1 is " +
                                           found + ", expected one of " + known);
  }
  throw psx::InputError::whole(path, "the disc has no data track");
}

std::int64_t Env::raw(const Variable& v) const {
  switch (v.type) {
    case Variable::Type::U8: return console_->read8(v.address);
    case Variable::Type::S8: return static_cast<std::int8_t>(console_->read8(v.address));
    case Variable::Type::U16: return console_->read16(v.address);
    case Variable::Type::S16: return static_cast<std::int16_t>(console_->read16(v.address));
    case Variable::Type::U32: return console_->read32(v.address);
    case Variable::Type::S32: return static_cast<std::int32_t>(console_->read32(v.address));
  }
  return 0;
}

void Env::write_raw(const Variable& v, std::int64_t value) {
  switch (v.width()) {
    case 1: console_->write8(v.address, static_cast<std::uint8_t>(value)); break;
    case 2: console_->write16(v.address, static_cast<std::uint16_t>(value)); break;
    default: console_->write32(v.address, static_cast<std::uint32_t>(value)); break;
  }
}

double Env::value(const std::string& name) const {
  const Variable& v = game_.variable(name);
  return static_cast<double>(raw(v)) * v.scale;
}

void Env::set_delays(std::uint32_t initial_delay, std::uint32_t delay) {
  if (delay == 0) throw std::invalid_argument("the delay must be at least one frame");
  delim_.initial_delay = initial_delay;
  delim_.delay = delay;
}

std::uint64_t Env::next_random() { return splitmix64(rng_); }

const LevelMap& Env::map() const {
  auto& slot = maps_[static_cast<size_t>(level_)];
  if (!slot) {
    if (game_.map_pattern.find("{maps}") != std::string::npos && config_.files.maps_dir.empty())
      throw psx::InputError("game '" + game_.name + "' needs level maps for this observation: pass --maps DIR (see " +
                            game_.folder + "/README.md)");
    slot = read_level_map(expand(game_.map_pattern, level_, game_, config_.files));
  }
  return *slot;
}

std::uint64_t Env::start_level(int level) {
  if (game_.level_start == Integration::LevelStart::State) {
    if (game_.state_pattern.find("{states}") != std::string::npos && config_.files.states_dir.empty())
      throw psx::InputError("game '" + game_.name + "' starts levels from your save states: pass --states DIR (see " +
                            game_.folder + "/README.md)");
    console_->load_state_file(expand(game_.state_pattern, level, game_, config_.files));
  } else {
    console_->restore(boot_state_);
  }
  std::uint64_t f0 = console_->frames();
  if (lua_->has_function("on_reset")) lua_->call("on_reset", {double(level), double(rng_ & 0xFFFFFFFFu)}, 0);
  if (game_.level_start == Integration::LevelStart::Request) {
    write_raw(game_.variable(game_.request_variable), level);
  } else if (game_.level_start == Integration::LevelStart::Script) {
    lua_->call("start_level", {double(level)}, 0);
  }
  if (!game_.level_ready.variable.empty()) {
    const Variable& v = game_.variable(game_.level_ready.variable);
    auto ready = [&] { return contains_value(game_.level_ready.values, raw(v)); };
    if (game_.level_start == Integration::LevelStart::Request) console_->run_frame();
    if (!console_->run_until(ready, game_.level_max_frames))
      throw psx::InputError::whole(game_.manifest, "[levels] ready: level " + std::to_string(level) +
                                                       " did not start within " + std::to_string(game_.level_max_frames) +
                                                       " frames");
  }
  return console_->frames() - f0;
}

const Observation& Env::reset(int level, std::uint64_t seed, StepInfo* info) {
  auto t0 = std::chrono::steady_clock::now();
  if (level < 1 || level > game_.level_count)
    throw std::out_of_range("level " + std::to_string(level) + ": game '" + game_.name + "' has levels 1 to " +
                            std::to_string(game_.level_count));
  rng_ = seed;
  level_ = level;
  std::uint64_t frames = start_level(level);
  return begin_episode(level, seed, game_.time_variable.empty() ? 0 : value(game_.time_variable), frames, t0, info);
}

const Observation& Env::begin_episode(int level, std::uint64_t seed, double time_at_start, std::uint64_t frames,
                                      std::chrono::steady_clock::time_point t0, StepInfo* info) {
  rng_ = seed;
  level_ = level;
  std::vector<psx::StereoSample> discard;
  console_->take_audio(discard);
  moves_ = 0;
  episode_frames_ = 0;
  episode_reward_ = 0;
  last_action_ = 0;
  done_ = false;
  time_at_start_ = time_at_start;
  move_audio_.clear();
  encode();
  if (info) *info = make_info(frames, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return obs_;
}

Env::Snapshot Env::snapshot() {
  if (level_ == 0) throw std::logic_error("snapshot() before reset(): no episode to save");
  Snapshot s{level_, time_at_start_, {}};
  console_->snapshot(s.console);
  return s;
}

const Observation& Env::reset_to(const Snapshot& s, std::uint64_t seed, StepInfo* info) {
  auto t0 = std::chrono::steady_clock::now();
  if (s.level < 1 || s.level > game_.level_count)
    throw std::out_of_range("snapshot of level " + std::to_string(s.level) + ": game '" + game_.name +
                            "' has levels 1 to " + std::to_string(game_.level_count));
  console_->restore(s.console);
  return begin_episode(s.level, seed, s.time_at_start, 0, t0, info);
}

}  // namespace psxrl::rl
