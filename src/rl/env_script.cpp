// What an integration's Lua script can do to its environment: the `env` table (reading and writing
// the integration's variables, running frames, pressing buttons, reading the level map). The
// script defines the optional hooks on_reset, start_level, after_move, position, outcome and
// reward (docs/integrating-a-game.md lists them with their arguments).
#include <lua.hpp>

#include "core/console.h"
#include "core/sio/pad_names.h"
#include "lua/lua_host.h"
#include "rl/env.h"

namespace psxrl::rl {

void Env::bind_script() {
  using lua::Host;
  auto var = [this](lua_State* L, int i) -> const Variable& {
    std::string name = Host::string_arg(L, i);
    const Variable* v = game_.find_variable(name);
    if (!v) throw std::invalid_argument("unknown variable '" + name + "' (declare it under [variables])");
    return *v;
  };
  lua_->add_function("env", "get", [this, var](lua_State* L) {
    const Variable& v = var(L, 1);
    lua_pushnumber(L, static_cast<double>(raw(v)) * v.scale);
    return 1;
  });
  lua_->add_function("env", "raw", [this, var](lua_State* L) {
    lua_pushinteger(L, raw(var(L, 1)));
    return 1;
  });
  lua_->add_function("env", "set", [this, var](lua_State* L) {
    write_raw(var(L, 1), static_cast<std::int64_t>(Host::number_arg(L, 2)));
    return 0;
  });
  lua_->add_function("env", "level", [this](lua_State* L) {
    lua_pushinteger(L, level_);
    return 1;
  });
  lua_->add_function("env", "run_frames", [this](lua_State* L) {
    double n = Host::number_arg(L, 1);
    if (n < 0 || n > 100000) throw std::invalid_argument("run_frames: expected 0 to 100000 frames");
    console_->run_frames(static_cast<std::uint64_t>(n));
    return 0;
  });
  // env.press("cross+up", frames): runs `frames` frames with the buttons down on port 1, then one
  // frame with them up, so that the game sees the release and two presses in a row are two
  // presses (down edges), not one long hold. Returns when those frames + 1 have run.
  lua_->add_function("env", "press", [this](lua_State* L) {
    std::string names = Host::string_arg(L, 1);
    double frames = Host::number_arg(L, 2);
    psx::u16 bits = 0;
    for (size_t start = 0; start <= names.size();) {
      size_t plus = names.find('+', start);
      std::string one = names.substr(start, plus == std::string::npos ? std::string::npos : plus - start);
      auto bit = psx::pad_button_from_name(one);
      if (!bit) throw std::invalid_argument("press: unknown button '" + one + "' (expected " + psx::kPadButtonNameList + ")");
      bits |= *bit;
      if (plus == std::string::npos) break;
      start = plus + 1;
    }
    if (frames < 1 || frames > 100000) throw std::invalid_argument("press: expected 1 to 100000 frames");
    console_->press(1, bits);
    console_->run_frames(static_cast<std::uint64_t>(frames));
    console_->release(1, bits);
    console_->run_frame();
    return 0;
  });
  // env.map() -> width, height, start_x, start_y, facing of the current level's map.
  lua_->add_function("env", "map", [this](lua_State* L) {
    const LevelMap& m = map();
    for (int v : {m.width, m.height, m.start_x, m.start_y, m.facing}) lua_pushinteger(L, v);
    return 5;
  });
  // env.tile(x, y) -> the map character there ('.' outside the map).
  lua_->add_function("env", "tile", [this](lua_State* L) {
    char c = static_cast<char>(map().at(static_cast<int>(Host::number_arg(L, 1)), static_cast<int>(Host::number_arg(L, 2))));
    lua_pushlstring(L, &c, 1);
    return 1;
  });
}

}  // namespace psxrl::rl
