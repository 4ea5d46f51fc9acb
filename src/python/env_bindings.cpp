// psxrl.Env and psxrl.VecEnv over src/rl (docs/environments.md): keyword arguments mirror
// EnvConfig, observations are NumPy arrays (a dict of them for multimodal), infos are dicts with
// the seed's §3.2.7 fields. Env returns copies, since the environment overwrites its buffers at
// every call; VecEnv returns read-only views of its batch buffers (no copy), which the next
// reset/step overwrites. Booting, resetting and stepping release the GIL.
#include <algorithm>
#include <climits>
#include <thread>

#include <pybind11/stl.h>

#include "core/console.h"
#include "python/arguments.h"
#include "python/bindings.h"
#include "rl/env.h"
#include "rl/agents/start_position.h"
#include "rl/async_vec_env.h"
#include "rl/vec_env.h"

namespace py = pybind11;
namespace rl = psxrl::rl;

namespace psxrl::python {
namespace {

using R = py::gil_scoped_release;

std::string path_of(py::handle v) { return py::str(py::module_::import("os").attr("fspath")(v)); }

// EnvConfig from keyword arguments; None keeps a field's default (the integration's value for the
// optional overrides). An unknown keyword is a TypeError, as for any Python function.
rl::EnvConfig config_from(const py::kwargs& kw) {
  constexpr long long kU32 = 0xFFFFFFFFll;
  auto u32 = [](const char* name, py::handle v, long long lo) {
    return static_cast<std::uint32_t>(int_arg(name, v, lo, kU32));
  };
  rl::EnvConfig c;
  for (auto [k, v] : kw) {
    std::string key = py::str(k);
    const char* n = key.c_str();
    if (v.is_none()) continue;
    if (key == "game") c.game = string_arg(n, v);
    else if (key == "games_dir") c.games_dir = path_of(v);
    else if (key == "build_games_dir") c.build_games_dir = path_of(v);
    else if (key == "disc") c.files.disc = path_of(v);
    else if (key == "bios") c.files.bios = path_of(v);
    else if (key == "states") c.files.states_dir = path_of(v);
    else if (key == "maps") c.files.maps_dir = path_of(v);
    else if (key == "obs") c.obs = string_arg(n, v);
    else if (key == "visual_gray") c.visual_gray = bool_arg(n, v);
    else if (key == "reward") c.reward = string_arg(n, v);
    else if (key == "gamma") c.gamma = number_arg(n, v);
    else if (key == "initial_delay") c.initial_delay = u32(n, v, 0);
    else if (key == "delay") c.delay = u32(n, v, 1);
    else if (key == "max_move_frames") c.max_move_frames = u32(n, v, 1);
    else if (key == "max_moves") c.max_moves = u32(n, v, 1);
    else if (key == "sticky") c.sticky = number_arg(n, v);
    else if (key == "renderer") c.renderer = string_arg(n, v);
    else if (key == "scale") c.scale = u32(n, v, 1);
    else if (key == "cpu") c.cpu = string_arg(n, v);
    else throw py::type_error("unexpected keyword argument '" + key + "'");
  }
  if (c.sticky && !(*c.sticky >= 0 && *c.sticky <= 1)) throw py::value_error("sticky: expected 0 to 1");
  return c;
}

py::dtype dtype_of(rl::DType d) {
  switch (d) {
    case rl::DType::U8: return py::dtype::of<std::uint8_t>();
    case rl::DType::I64: return py::dtype::of<std::int64_t>();
    case rl::DType::F32: return py::dtype::of<float>();
  }
  return py::dtype::of<float>();
}

// One observation array, `batch` environments deep (0: a single environment's array). Without a
// base the data is copied; with one the array views it and keeps the base alive.
py::array part_array(const rl::Space& s, const void* data, int batch, py::handle base) {
  std::vector<py::ssize_t> shape;
  if (batch > 0) shape.push_back(batch);
  for (std::int64_t d : s.shape) shape.push_back(d);
  std::vector<py::ssize_t> strides = c_strides(shape, rl::dtype_size(s.dtype));
  if (!base) return py::array(dtype_of(s.dtype), shape, strides, data);
  return read_only(py::array(dtype_of(s.dtype), shape, strides, data, base));
}

// A single-array observation is that array; multimodal is a dict by part name.
py::object observation(const std::vector<rl::Space>& spaces, const std::vector<const void*>& data, int batch,
                       py::handle base) {
  if (spaces.size() == 1) return part_array(spaces[0], data[0], batch, base);
  py::dict d;
  for (size_t i = 0; i < spaces.size(); ++i) d[py::str(spaces[i].name)] = part_array(spaces[i], data[i], batch, base);
  return d;
}

py::object env_observation(const rl::Env& e) {
  std::vector<const void*> data;
  for (const rl::ObsPart& p : e.observation()) data.push_back(p.data);
  return observation(e.observation_spaces(), data, 0, py::handle());
}

py::object batch_observation(const std::vector<rl::Space>& spaces, const std::vector<std::vector<std::uint8_t>>& buf,
                             int n, py::handle base) {
  std::vector<const void*> data;
  for (const auto& b : buf) data.push_back(b.data());
  return observation(spaces, data, n, base);
}

py::dict info_dict(const rl::StepInfo& i) {
  py::dict d;
  d["game_frames"] = i.game_frames;
  d["real_seconds"] = i.real_seconds;
  d["score"] = i.score;
  d["time_left"] = i.time_left;
  d["state"] = i.state;
  d["level"] = i.level;
  d["hit_upper_bound"] = i.hit_upper_bound;
  d["moves"] = i.moves;
  d["episode_reward"] = i.episode_reward;
  d["outcome"] = i.outcome;
  return d;
}

py::list spaces_list(const std::vector<rl::Space>& spaces) {
  py::list l;
  for (const rl::Space& s : spaces) {
    py::dict d;
    d["name"] = s.name;
    d["shape"] = py::tuple(py::cast(s.shape));
    d["dtype"] = rl::dtype_name(s.dtype);
    d["low"] = s.low;
    d["high"] = s.high;
    l.append(d);
  }
  return l;
}

py::list action_names(const std::vector<rl::Action>& actions) {
  py::list l;
  for (const rl::Action& a : actions) l.append(a.name);
  return l;
}

py::dict delimiter_dict(const rl::DelimiterSettings& s) {
  py::dict d;
  d["initial_delay"] = s.initial_delay;
  d["delay"] = s.delay;
  d["max_move_frames"] = s.max_frames;
  return d;
}

}  // namespace

void bind_env(py::module_& m) {
  m.def("default_games_dir", &rl::default_games_dir,
        "The integrations' folder an Env uses without games_dir: $PSXRL_GAMES, else the source tree's games/.");
  m.def("episode_seed", &rl::episode_seed, py::arg("seed"), py::arg("env_index"), py::arg("episode"),
        "The seed VecEnv gives environment `env_index`'s `episode`-th episode (0 = the one reset() starts).");

  py::class_<rl::Env>(m, "Env", "One environment: a console, a Lua state and a game integration.")
      .def(py::init([](const py::kwargs& kw) {
        rl::EnvConfig c = config_from(kw);
        R release;
        return std::make_unique<rl::Env>(c);
      }))
      .def(
          "reset",
          [](rl::Env& e, py::handle level_arg, py::handle seed_arg, py::handle start_arg) {
            int level = static_cast<int>(int_arg("level", level_arg, INT_MIN, INT_MAX));
            std::uint64_t seed = u64_arg("seed", seed_arg);
            // A start position (psxrl train --start): the walk, then an episode that begins there.
            agents::StartPosition start = agents::parse_start_position(string_arg("start", start_arg), e.actions());
            rl::StepInfo info;
            auto held = e.hold();
            {
              R release;
              agents::begin_at(e, level, start, seed, &info);
            }
            return py::make_tuple(env_observation(e), info_dict(info));
          },
          py::arg("level") = 1, py::arg("seed") = 0, py::arg("start") = "")
      .def(
          "step",
          [](rl::Env& e, py::handle action_arg) {
            int action = static_cast<int>(int_arg("action", action_arg, INT_MIN, INT_MAX));
            rl::StepResult r;
            auto held = e.hold();
            {
              R release;
              r = e.step(action);
            }
            return py::make_tuple(env_observation(e), r.reward, r.terminated, r.truncated, info_dict(r.info));
          },
          py::arg("action"))
      .def("close", &rl::Env::close, py::call_guard<R>(),
           "Releases the console and the Lua state now; any later reset, step or console call raises "
           "RuntimeError('Env is closed'). Closing twice is allowed.")
      .def_property_readonly("closed", &rl::Env::closed)
      .def(
          "observation",
          [](const rl::Env& e) {
            auto held = e.hold();
            return env_observation(e);
          },
          "The current observation (a copy).")
      .def_property_readonly("observation_spaces", [](const rl::Env& e) { return spaces_list(e.observation_spaces()); })
      .def_property_readonly("obs", [](const rl::Env& e) { return rl::obs_kind_name(e.obs_kind()); })
      .def_property_readonly("game", [](const rl::Env& e) { return e.game().name; })
      .def_property_readonly("action_count", &rl::Env::action_count)
      .def_property_readonly("action_names", [](const rl::Env& e) { return action_names(e.actions()); })
      .def_property_readonly("level", &rl::Env::level)
      .def_property_readonly("episode_over", &rl::Env::episode_over)
      .def("set_delays", &rl::Env::set_delays, py::arg("initial_delay"), py::arg("delay"))
      .def_property_readonly("delimiter", [](const rl::Env& e) { return delimiter_dict(e.delimiter_settings()); })
      .def("value", &rl::Env::value, py::arg("variable"), "A named variable of the integration, scaled.")
      .def(
          "get_screen",
          [](rl::Env& e) {
            psx::Console::Frame f = e.console().frame();
            py::ssize_t w = f.width, h = f.height;
            return array_of<std::uint8_t>({h, w, 3}, f.rgb);
          },
          "The displayed picture as a [height, width, 3] uint8 array (a copy).");

  py::class_<rl::VecEnv>(m, "VecEnv", "N environments stepped together on a thread pool, with same-step autoreset.")
      .def(py::init([](int num_envs, unsigned threads, const py::kwargs& kw) {
             rl::EnvConfig c = config_from(kw);
             if (threads == 0)
               threads = std::min<unsigned>(static_cast<unsigned>(std::max(num_envs, 1)),
                                            std::max(1u, std::thread::hardware_concurrency()));
             R release;
             return std::make_unique<rl::VecEnv>(c, num_envs, threads);
           }),
           py::arg("num_envs"), py::arg("threads") = 0)
      .def(
          "reset",
          [](py::object self, int level, std::uint64_t seed) {
            auto& v = self.cast<rl::VecEnv&>();
            {
              R release;
              v.reset(level, seed);
            }
            return batch_observation(v.observation_spaces(), v.batch(), v.size(), self);
          },
          py::arg("level") = 1, py::arg("seed") = 0)
      .def(
          "step",
          [](py::object self, const py::array_t<int, py::array::c_style | py::array::forcecast>& actions) {
            auto& v = self.cast<rl::VecEnv&>();
            std::vector<int> a(actions.data(), actions.data() + actions.size());
            const rl::VecStep* s;
            {
              R release;
              s = &v.step(a);
            }
            py::list infos;
            for (const rl::StepInfo& i : s->infos) infos.append(info_dict(i));
            // The flags are 0/1 bytes, which is exactly NumPy's bool layout.
            auto flags = [](const std::vector<std::uint8_t>& f) {
              return array_of<bool>({static_cast<py::ssize_t>(f.size())}, reinterpret_cast<const bool*>(f.data()));
            };
            return py::make_tuple(batch_observation(v.observation_spaces(), v.batch(), v.size(), self),
                                  array_of<double>({static_cast<py::ssize_t>(s->rewards.size())}, s->rewards.data()),
                                  flags(s->terminated), flags(s->truncated), infos);
          },
          py::arg("actions"))
      .def(
          "observation",
          [](py::object self) {
            auto& v = self.cast<rl::VecEnv&>();
            return batch_observation(v.observation_spaces(), v.batch(), v.size(), self);
          },
          "The current batch: read-only views, overwritten by the next reset() or step().")
      .def(
          "final_observation",
          [](py::object self) {
            auto& v = self.cast<rl::VecEnv&>();
            return batch_observation(v.observation_spaces(), v.final_batch(), v.size(), self);
          },
          "Views of each environment's last observation of its latest finished episode (rows of environments "
          "whose episode has not ended yet are stale or zero).")
      .def_property_readonly("num_envs", &rl::VecEnv::size)
      .def_property_readonly("threads", &rl::VecEnv::threads)
      .def_property_readonly("observation_spaces",
                             [](const rl::VecEnv& v) { return spaces_list(v.observation_spaces()); })
      .def_property_readonly("action_count", &rl::VecEnv::action_count);

  py::class_<rl::AsyncVecEnv>(m, "AsyncVecEnv",
                              "N environments stepped asynchronously (EnvPool's send/recv): recv() returns the first "
                              "batch_size environments to finish, with their ids.")
      .def(py::init([](int num_envs, int batch_size, unsigned threads, const py::kwargs& kw) {
             rl::EnvConfig c = config_from(kw);
             if (batch_size == 0) batch_size = num_envs;
             if (threads == 0)
               threads = std::min<unsigned>(static_cast<unsigned>(std::max(num_envs, 1)),
                                            std::max(1u, std::thread::hardware_concurrency()));
             R release;
             return std::make_unique<rl::AsyncVecEnv>(c, num_envs, batch_size, threads);
           }),
           py::arg("num_envs"), py::arg("batch_size") = 0, py::arg("threads") = 0)
      .def(
          "reset",
          [](rl::AsyncVecEnv& v, int level, std::uint64_t seed) {
            R release;
            v.reset(level, seed);
          },
          py::arg("level") = 1, py::arg("seed") = 0,
          "Starts every environment on the level in the background; recv() returns them.")
      .def(
          "send",
          [](rl::AsyncVecEnv& v, const py::array_t<int, py::array::c_style | py::array::forcecast>& actions,
             const py::array_t<int, py::array::c_style | py::array::forcecast>& env_ids) {
            std::vector<int> a(actions.data(), actions.data() + actions.size());
            std::vector<int> ids(env_ids.data(), env_ids.data() + env_ids.size());
            R release;
            v.send(a, ids);
          },
          py::arg("actions"), py::arg("env_ids"))
      .def(
          "recv",
          [](py::object self) {
            auto& v = self.cast<rl::AsyncVecEnv&>();
            const rl::AsyncBatch* b;
            {
              R release;
              b = &v.recv();
            }
            py::list infos;
            for (const rl::StepInfo& i : b->infos) infos.append(info_dict(i));
            const auto n = static_cast<py::ssize_t>(b->env_ids.size());
            auto flags = [n](const std::vector<std::uint8_t>& f) {
              return array_of<bool>({n}, reinterpret_cast<const bool*>(f.data()));
            };
            return py::make_tuple(batch_observation(v.observation_spaces(), b->observations, v.batch_size(), self),
                                  array_of<double>({n}, b->rewards.data()), flags(b->terminated), flags(b->truncated),
                                  infos, array_of<int>({n}, b->env_ids.data()));
          },
          "(observations, rewards, terminated, truncated, infos, env_ids) of the next batch_size environments to "
          "finish; the observation views are overwritten by the next recv().")
      .def(
          "final_observation",
          [](py::object self) {
            auto& v = self.cast<rl::AsyncVecEnv&>();
            return batch_observation(v.observation_spaces(), v.last_batch().final_observations, v.batch_size(), self);
          },
          "Views of the last observation of each episode that ended in the latest recv() batch (other rows are stale).")
      .def_property_readonly("num_envs", &rl::AsyncVecEnv::size)
      .def_property_readonly("batch_size", &rl::AsyncVecEnv::batch_size)
      .def_property_readonly("threads", &rl::AsyncVecEnv::threads)
      .def_property_readonly("observation_spaces",
                             [](const rl::AsyncVecEnv& v) { return spaces_list(v.observation_spaces()); })
      .def_property_readonly("action_count", &rl::AsyncVecEnv::action_count);
}

}  // namespace psxrl::python
