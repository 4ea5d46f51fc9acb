// Env::step: running a move (delimited, seed §3.2.4) or a frame-skip step (ALE style), the
// reward (seed Table 3.3 or raw score), the outcome, and encoding the observation.
#include <chrono>
#include <stdexcept>
#include <utility>

#include "core/console.h"
#include "lua/lua_host.h"
#include "rl/env.h"

namespace psxrl::rl {

bool Env::samples_taken() const {
  // The audio observations and a front end's on_frame (a window's speaker, a recording) take the
  // samples; nothing else does.
  return obs_kind_ == ObsKind::Audio || obs_kind_ == ObsKind::Multimodal || on_frame != nullptr;
}

void Env::listen() {
  // Sound is mixed only for what takes it. A move delimiter that waits for silence needs only to
  // know whether each frame got loud: the SPU watches for that, and where nothing takes the
  // samples it mixes a frame only until its first loud sample.
  console_->set_sound_observed(samples_taken());
  const bool delimiter = game_.mode == Integration::StepMode::Moves && game_.watch_audio;
  console_->watch_loudness(delimiter ? std::optional<psx::u16>(game_.audio_threshold) : std::nullopt);
}

void Env::frame_done(std::vector<std::int64_t>* watched, bool* activity) {
  frame_audio_.clear();
  console_->take_audio(frame_audio_);
  if (on_frame) on_frame(frame_audio_);
  if (!console_->fatal_error().empty())
    throw std::runtime_error("game '" + game_.name + "': the console stopped: " + console_->fatal_error());
  bool active = console_->take_loud();  // false without a loudness watch (listen())
  if (obs_kind_ == ObsKind::Audio || obs_kind_ == ObsKind::Multimodal)
    move_audio_.insert(move_audio_.end(), frame_audio_.begin(), frame_audio_.end());
  if (watched) {
    for (size_t i = 0; i < watched_vars_.size(); ++i) {
      std::int64_t now = raw(*watched_vars_[i]);
      active |= now != (*watched)[i];
      (*watched)[i] = now;
    }
  }
  if (activity) *activity = active;
}

void Env::run_move(const Action& a, bool& hit_bound) {
  std::vector<std::int64_t> watched;
  for (const Variable* v : watched_vars_) watched.push_back(raw(*v));
  console_->press_for(1, a.buttons, a.hold);
  MoveDelimiter delimiter;
  delimiter.begin(delim_);
  for (;;) {
    console_->run_frame();
    bool activity = false;
    frame_done(&watched, &activity);
    // A win or a loss ends the move at once: nothing the agent does next can change it.
    if (!outcome().empty()) break;
    if (delimiter.frame(activity)) break;
  }
  hit_bound = delimiter.hit_bound();
}

void Env::run_frames(int action) {
  std::uint32_t skip = game_.frame_skip_min;
  if (game_.frame_skip_max > game_.frame_skip_min)
    skip += static_cast<std::uint32_t>(next_random() % (game_.frame_skip_max - game_.frame_skip_min + 1));
  for (std::uint32_t frames = 0; frames < skip && outcome().empty(); ++frames) {
    // Sticky actions (Machado et al.): each frame keeps the previous action with probability p.
    if (sticky_ > 0 && static_cast<double>(next_random() >> 11) * 0x1.0p-53 < sticky_) action = last_action_;
    last_action_ = action;
    // The buttons are down for the action's first `hold` frames and up for the rest of the step,
    // so a game that acts on presses (a button's down edge) sees the same action twice in a row
    // as two presses; a hold of at least the frame skip keeps them down for the whole step.
    const Action& a = game_.actions[static_cast<size_t>(action)];
    console_->set_buttons(1, frames < a.hold ? a.buttons : psx::u16{0});
    console_->run_frame();
    frame_done(nullptr, nullptr);
  }
  console_->set_buttons(1, 0);
}

StepResult Env::step(int action) {
  psx::ThreadOwner::Use use(owner_);
  check_open();
  auto t0 = std::chrono::steady_clock::now();
  if (done_) throw std::logic_error("step() after the episode ended: call reset() first");
  if (action < 0 || action >= action_count())
    throw std::out_of_range("action " + std::to_string(action) + ": game '" + game_.name + "' has actions 0 to " +
                            std::to_string(action_count() - 1));
  const Variable* score = game_.score_variable.empty() ? nullptr : &game_.variable(game_.score_variable);
  std::int64_t score0 = score ? raw(*score) : 0;
  move_audio_.clear();
  listen();
  bool hit_bound = false;
  const std::uint64_t f0 = console_->frames();
  if (game_.mode == Integration::StepMode::Moves) run_move(game_.actions[static_cast<size_t>(action)], hit_bound);
  else run_frames(action);
  if (lua_->has_function("after_move")) lua_->call("after_move", {double(action)}, 0);
  // Every frame the console ran counts, the script's in after_move included.
  const std::uint64_t frames = console_->frames() - f0;
  StepResult r;
  std::string out = outcome();
  r.reward = move_reward(score ? raw(*score) - score0 : 0, out);
  ++moves_;
  episode_frames_ += frames;
  episode_reward_ += r.reward;
  r.terminated = !out.empty();
  r.truncated = !r.terminated && (moves_ >= max_moves_ || (game_.max_frames && episode_frames_ >= game_.max_frames));
  done_ = r.terminated || r.truncated;
  encode();
  r.info = make_info(frames, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  r.info.hit_upper_bound = hit_bound;
  return r;
}

std::string Env::outcome() const {
  if (script_outcome_) {
    auto o = lua_->call_string("outcome", {});
    if (o && *o != "win" && *o != "lose") throw psx::InputError(game_.script + ": outcome() must return \"win\", \"lose\" or nil");
    return o.value_or("");
  }
  std::int64_t state = raw(*state_var_);
  if (contains_value(game_.win_states, state)) return "win";
  if (contains_value(game_.lose_states, state)) return "lose";
  return "";
}

double Env::move_reward(std::int64_t delta, const std::string& out) const {
  if (reward_kind_ == RewardKind::Score) return static_cast<double>(delta);
  if (reward_kind_ == RewardKind::Script) {
    double code = out == "win" ? 1 : out == "lose" ? -1 : 0;
    return lua_->call("reward", {double(delta), code}, 1)[0].value_or(0.0);
  }
  // Seed Table 3.3: each score increase the table names earns its share of (1 - gamma);
  // a move that collects several items earns each one's (largest first).
  double units = 0;
  for (const auto& [points, reward] : game_.item_rewards)
    for (; points > 0 && delta >= points; delta -= points) units += reward;
  if (out == "win") units += game_.win_reward;
  if (out == "lose") units += game_.lose_reward;
  return units * (1.0 - config_.gamma);
}

void Env::position(int& x, int& y, int& facing) const {
  if (!game_.position_x.empty()) {
    x = static_cast<int>(raw(game_.variable(game_.position_x)));
    y = static_cast<int>(raw(game_.variable(game_.position_y)));
    facing = static_cast<int>(raw(game_.variable(game_.position_facing)));
    return;
  }
  auto p = lua_->call("position", {}, 3);
  if (!p[0] || !p[1] || !p[2]) throw psx::InputError(game_.script + ": position() must return x, y and facing");
  x = static_cast<int>(*p[0]), y = static_cast<int>(*p[1]), facing = static_cast<int>(*p[2]);
}

void Env::encode() {
  obs_.clear();
  auto episode = [&](float* out) {
    double time = game_.time_variable.empty() ? 0 : value(game_.time_variable);
    out[0] = static_cast<float>(episode_reward_);
    out[1] = static_cast<float>(time_at_start_ > 0 ? time / time_at_start_ : 0);
    out[2] = static_cast<float>(static_cast<double>(moves_) / max_moves_);
  };
  auto visual = [&] {
    auto f = console_->native_frame();
    visual_planes(f.rgb, static_cast<int>(f.width), static_cast<int>(f.height), game_.visual_x, game_.visual_y,
                  game_.visual_w, game_.visual_h, game_.visual_out_w, game_.visual_out_h, config_.visual_gray,
                  visual_buf_.data());
    return visual_buf_.data();
  };
  auto audio = [&] {
    audio_mfcc(move_audio_, static_cast<int>(game_.audio_threshold), game_.audio_frames, audio_buf_.data());
    return audio_buf_.data();
  };
  int x = 0, y = 0, facing = 0;
  switch (obs_kind_) {
    case ObsKind::Simple:
      position(x, y, facing);
      simple_buf_[0] = simple_index(map(), x, y, facing);
      obs_.push_back({&spaces_[0], simple_buf_.data()});
      break;
    case ObsKind::Local: {
      position(x, y, facing);
      local_crop(map(), x, y, facing, game_.local_ahead, game_.local_behind, game_.local_side, local_buf_.data());
      float ep[3];
      episode(ep);
      local_buf_[local_buf_.size() - 2] = ep[0];
      local_buf_[local_buf_.size() - 1] = ep[1];
      obs_.push_back({&spaces_[0], local_buf_.data()});
      break;
    }
    case ObsKind::Episode:
      episode(episode_buf_.data());
      obs_.push_back({&spaces_[0], episode_buf_.data()});
      break;
    case ObsKind::Ram: obs_.push_back({&spaces_[0], std::as_const(*console_).ram().data()}); break;
    case ObsKind::Rumble: {
      auto r = console_->rumble(1);
      rumble_buf_ = {r.small, r.large};
      obs_.push_back({&spaces_[0], rumble_buf_.data()});
      break;
    }
    case ObsKind::Audio: obs_.push_back({&spaces_[0], audio()}); break;
    case ObsKind::Visual: obs_.push_back({&spaces_[0], visual()}); break;
    case ObsKind::Multimodal:
      obs_.push_back({&spaces_[0], visual()});
      episode(episode_buf_.data());
      obs_.push_back({&spaces_[1], episode_buf_.data()});
      obs_.push_back({&spaces_[2], audio()});
      break;
  }
}

StepInfo Env::make_info(std::uint64_t frames, double seconds) const {
  StepInfo i;
  i.game_frames = frames;
  i.real_seconds = seconds;
  i.score = game_.score_variable.empty() ? 0 : raw(game_.variable(game_.score_variable));
  i.time_left = game_.time_variable.empty() ? 0 : value(game_.time_variable);
  i.state = raw(*state_var_);
  i.level = level_;
  i.moves = moves_;
  i.episode_reward = episode_reward_;
  i.outcome = outcome();
  return i;
}

}  // namespace psxrl::rl
