// game.toml reader (see integration.h). toml++ keeps each node's source line, so every error
// names the file, the line and the field it is about.
#include "rl/integration.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <toml++/toml.h>

#include "core/input_error.h"
#include "core/sio/pad_names.h"

namespace psxrl::rl {

namespace fs = std::filesystem;

namespace {

// Typed access to one table of the manifest with errors that say file:line: [table] key: ...
class Reader {
 public:
  Reader(const std::string& file, const toml::table& t, std::string path) : file_(file), t_(t), path_(std::move(path)) {}

  [[noreturn]] void fail(const toml::node* at, const std::string& key, const std::string& what) const {
    throw psx::InputError(message(at, key, what));
  }
  // "file:line: [table] key: what", the line of `at` (else of the table).
  std::string message(const toml::node* at, const std::string& key, const std::string& what) const {
    auto line = at ? at->source().begin.line : t_.source().begin.line;
    std::string where = path_.empty() ? key : "[" + path_ + "] " + key;
    return psx::InputError::at_line(file_, line, where + ": " + what).what();
  }
  const toml::node* get(const std::string& key) const { return t_.get(key); }
  bool has(const std::string& key) const { return t_.contains(key); }

  std::string str(const std::string& key, const std::string& fallback, bool required = false) const {
    const toml::node* n = get(key);
    if (!n) {
      if (required) fail(nullptr, key, "missing (expected a string)");
      return fallback;
    }
    if (!n->is_string()) fail(n, key, "expected a string");
    return n->as_string()->get();
  }
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi,
                       bool required = false) const {
    const toml::node* n = get(key);
    if (!n) {
      if (required) fail(nullptr, key, "missing (expected an integer)");
      return fallback;
    }
    if (!n->is_integer()) fail(n, key, "expected an integer");
    std::int64_t v = n->as_integer()->get();
    if (v < lo || v > hi) fail(n, key, "expected " + std::to_string(lo) + " to " + std::to_string(hi) + ", found " + std::to_string(v));
    return v;
  }
  double number(const std::string& key, double fallback, double lo, double hi) const {
    const toml::node* n = get(key);
    if (!n) return fallback;
    if (!n->is_number()) fail(n, key, "expected a number");
    double v = n->is_integer() ? static_cast<double>(n->as_integer()->get()) : n->as_floating_point()->get();
    if (v < lo || v > hi) fail(n, key, "expected a number from " + std::to_string(lo) + " to " + std::to_string(hi));
    return v;
  }
  bool boolean(const std::string& key, bool fallback) const {
    const toml::node* n = get(key);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(n, key, "expected true or false");
    return n->as_boolean()->get();
  }
  std::vector<std::int64_t> integers(const std::string& key) const {
    std::vector<std::int64_t> out;
    const toml::node* n = get(key);
    if (!n) return out;
    if (!n->is_array()) fail(n, key, "expected an array of integers");
    for (const auto& e : *n->as_array()) {
      if (!e.is_integer()) fail(&e, key, "expected an array of integers");
      out.push_back(e.as_integer()->get());
    }
    return out;
  }
  std::vector<std::string> strings(const std::string& key) const {
    std::vector<std::string> out;
    const toml::node* n = get(key);
    if (!n) return out;
    if (!n->is_array()) fail(n, key, "expected an array of strings");
    for (const auto& e : *n->as_array()) {
      if (!e.is_string()) fail(&e, key, "expected an array of strings");
      out.push_back(e.as_string()->get());
    }
    return out;
  }
  Reader table(const std::string& key, bool required) const {
    static const toml::table kEmpty;
    const toml::node* n = get(key);
    if (!n) {
      if (required) fail(nullptr, key, "missing table");
      return Reader(file_, kEmpty, key);
    }
    if (!n->is_table()) fail(n, key, "expected a table");
    return Reader(file_, *n->as_table(), path_.empty() ? key : path_ + "." + key);
  }
  void only(std::initializer_list<const char*> keys) const {
    for (const auto& [k, v] : t_) {
      if (std::none_of(keys.begin(), keys.end(), [&](const char* want) { return k.str() == want; }))
        fail(&v, std::string(k.str()), "unknown field");
    }
  }
  const toml::table& raw() const { return t_; }

 private:
  const std::string& file_;
  const toml::table& t_;
  std::string path_;
};

Variable::Type parse_type(const Reader& r, const std::string& key, const std::string& s) {
  static const std::pair<const char*, Variable::Type> kTypes[] = {
      {"u8", Variable::Type::U8}, {"s8", Variable::Type::S8}, {"u16", Variable::Type::U16},
      {"s16", Variable::Type::S16}, {"u32", Variable::Type::U32}, {"s32", Variable::Type::S32}};
  for (const auto& [n, t] : kTypes)
    if (s == n) return t;
  r.fail(r.get(key), key, "expected u8, s8, u16, s16, u32 or s32, found '" + s + "'");
}

void read_variables(const Reader& root, Integration& g) {
  Reader vars = root.table("variables", true);
  for (const auto& [key, node] : vars.raw()) {
    std::string name(key.str());
    if (!node.is_table()) vars.fail(&node, name, "expected a table { address = ..., type = ... }");
    Reader v(g.manifest, *node.as_table(), "variables." + name);
    v.only({"address", "type", "scale"});
    Variable var;
    var.name = name;
    var.address = static_cast<psx::u32>(v.integer("address", 0, 0, 0xFFFFFFFF, true));
    var.type = parse_type(v, "type", v.str("type", "u32"));
    var.scale = v.number("scale", 1.0, -1e9, 1e9);
    psx::u32 offset = var.address & 0x1FFFFFFF;
    if (offset + var.width() > 0x800000 || offset % var.width() != 0)
      v.fail(v.get("address"), "address", "expected an aligned address in RAM (0x80000000-0x801FFFFF or a mirror)");
    g.variables.push_back(var);
  }
}

void read_actions(const Reader& root, Integration& g) {
  const toml::node* n = root.get("actions");
  if (!n || !n->is_array_of_tables()) root.fail(n, "actions", "expected [[actions]] entries (name, buttons, hold)");
  for (const auto& e : *n->as_array()) {
    Reader a(g.manifest, *e.as_table(), "actions");
    a.only({"name", "buttons", "hold"});
    Action act;
    act.name = a.str("name", "", true);
    for (const auto& b : a.strings("buttons")) {
      auto bit = psx::pad_button_from_name(b);
      if (!bit) a.fail(a.get("buttons"), "buttons", "unknown button '" + b + "' (expected " + psx::kPadButtonNameList + ")");
      act.buttons |= *bit;
    }
    act.hold = static_cast<psx::u32>(a.integer("hold", 1, 1, 600));
    g.actions.push_back(act);
  }
  if (g.actions.empty()) root.fail(n, "actions", "expected at least one action");
}

Condition read_condition(const Reader& r, const std::string& key) {
  Reader c = r.table(key, false);
  Condition out;
  if (!r.has(key)) return out;
  c.only({"variable", "in"});
  out.variable = c.str("variable", "", true);
  out.values = c.integers("in");
  if (out.values.empty()) c.fail(c.get("in"), "in", "expected a non-empty array of values");
  return out;
}

// The integration's folder first, then the build's games/<name>/; when neither has the file,
// g.missing_program says where it was looked for (reported when the game boots).
std::string resolve_program(const Reader& boot, const std::string& key, const std::string& name, Integration& g,
                            const std::string& build_games_dir) {
  const fs::path places[] = {fs::path(g.folder), fs::path(build_games_dir) / g.name};
  for (const fs::path& dir : places)
    if (fs::is_regular_file(dir / name)) return (dir / name).string();
  g.missing_program = boot.message(boot.get(key), key, "'" + name + "' is in neither " + places[0].string() +
                                                           "/ nor " + places[1].string() + "/ (is the game built?)");
  return (places[1] / name).string();
}

// bios = "none" (the built-in kernel), "user" (--bios FILE) or { path = "FILE" }: a file relative
// to the integration's folder (or absolute), which --bios still overrides.
void read_bios(const Reader& b, Integration& g) {
  const char* expected = "expected \"none\", \"user\" or { path = \"FILE\" }";
  if (const toml::node* n = b.get("bios"); n && n->is_table()) {
    Reader t = b.table("bios", true);
    t.only({"path"});
    std::string path = t.str("path", "", true);
    if (path.empty()) t.fail(t.get("path"), "path", "expected a file name");
    g.bios = fs::path(path).is_absolute() ? path : (fs::path(g.folder) / path).string();
    g.needs_bios = true;
    return;
  }
  std::string bios = b.str("bios", "none");
  if (bios != "none" && bios != "user") b.fail(b.get("bios"), "bios", expected);
  g.needs_bios = bios == "user";
}

void read_boot(const Reader& root, Integration& g, const std::string& build_games_dir) {
  Reader b = root.table("boot", true);
  b.only({"exe", "disc", "bios", "disc_sha1", "ready", "max_frames"});
  std::string exe = b.str("exe", ""), disc = b.str("disc", "");
  if (exe.empty() == disc.empty()) b.fail(nullptr, "exe", "expected exactly one of exe = \"file\" or disc = \"file\" | \"user\"");
  if (!exe.empty()) g.exe = resolve_program(b, "exe", exe, g, build_games_dir);
  if (disc == "user") g.user_disc = true;
  else if (!disc.empty()) g.disc = resolve_program(b, "disc", disc, g, build_games_dir);
  read_bios(b, g);
  g.disc_sha1 = b.strings("disc_sha1");
  for (const auto& h : g.disc_sha1)
    if (h.size() != 40 || h.find_first_not_of("0123456789abcdef") != std::string::npos)
      b.fail(b.get("disc_sha1"), "disc_sha1", "expected SHA-1s as 40 lower-case hex digits, found '" + h + "'");
  g.boot_ready = read_condition(b, "ready");
  g.boot_max_frames = static_cast<psx::u32>(b.integer("max_frames", 600, 1, 100000));
}

void read_levels(const Reader& root, Integration& g) {
  Reader l = root.table("levels", true);
  l.only({"count", "start", "request_variable", "state", "maps", "ready", "max_frames"});
  g.level_count = static_cast<int>(l.integer("count", 1, 1, 999, true));
  std::string start = l.str("start", "request");
  if (start == "request") g.level_start = Integration::LevelStart::Request;
  else if (start == "state") g.level_start = Integration::LevelStart::State;
  else if (start == "script") g.level_start = Integration::LevelStart::Script;
  else l.fail(l.get("start"), "start", "expected \"request\", \"state\" or \"script\"");
  g.request_variable = l.str("request_variable", "", g.level_start == Integration::LevelStart::Request);
  g.state_pattern = l.str("state", "", g.level_start == Integration::LevelStart::State);
  g.map_pattern = l.str("maps", "");
  g.level_ready = read_condition(l, "ready");
  g.level_max_frames = static_cast<psx::u32>(l.integer("max_frames", 600, 1, 100000));
}

void read_moves(const Reader& root, Integration& g) {
  Reader m = root.table("moves", false);
  m.only({"mode", "watch", "audio", "audio_threshold", "initial_delay", "delay", "max_frames", "frame_skip", "sticky"});
  std::string mode = m.str("mode", "delimited");
  if (mode == "delimited") g.mode = Integration::StepMode::Moves;
  else if (mode == "frames") g.mode = Integration::StepMode::Frames;
  else m.fail(m.get("mode"), "mode", "expected \"delimited\" or \"frames\"");
  g.watch = m.strings("watch");
  g.watch_audio = m.boolean("audio", g.mode == Integration::StepMode::Moves);
  g.audio_threshold = static_cast<psx::u32>(m.integer("audio_threshold", 64, 0, 32767));
  g.initial_delay = static_cast<psx::u32>(m.integer("initial_delay", 6, 0, 10000));
  g.delay = static_cast<psx::u32>(m.integer("delay", 4, 1, 10000));
  g.max_move_frames = static_cast<psx::u32>(m.integer("max_frames", 600, 1, 100000));
  auto skip = m.integers("frame_skip");
  if (skip.size() == 1) skip.push_back(skip[0]);
  if (!skip.empty()) {
    if (skip.size() != 2 || skip[0] < 1 || skip[1] < skip[0] || skip[1] > 1000)
      m.fail(m.get("frame_skip"), "frame_skip", "expected [n] or [min, max] with 1 <= min <= max <= 1000");
    g.frame_skip_min = static_cast<psx::u32>(skip[0]);
    g.frame_skip_max = static_cast<psx::u32>(skip[1]);
  }
  g.sticky = m.number("sticky", 0.0, 0.0, 1.0);
}

void read_episode(const Reader& root, Integration& g) {
  Reader e = root.table("episode", true);
  e.only({"state", "win", "lose", "time", "max_moves", "max_frames"});
  g.state_variable = e.str("state", "", true);
  g.win_states = e.integers("win");
  g.lose_states = e.integers("lose");
  g.time_variable = e.str("time", "");
  g.max_moves = static_cast<psx::u32>(e.integer("max_moves", 1000, 1, 10'000'000));
  g.max_frames = static_cast<psx::u64>(e.integer("max_frames", 0, 0, INT64_MAX));
}

void read_reward(const Reader& root, Integration& g) {
  Reader r = root.table("reward", false);
  r.only({"score", "items", "win", "lose"});
  g.score_variable = r.str("score", "");
  const toml::node* items = r.get("items");
  if (items) {
    if (!items->is_table()) r.fail(items, "items", "expected a table of \"score increase\" = reward");
    for (const auto& [k, v] : *items->as_table()) {
      std::string key(k.str());
      if (key.empty() || key.find_first_not_of("0123456789") != std::string::npos || key.size() > 12)
        r.fail(&v, "items", "expected score increases as keys (e.g. 250 = 0.5), found '" + key + "'");
      if (!v.is_number()) r.fail(&v, "items." + key, "expected a number");
      double reward = v.is_integer() ? static_cast<double>(v.as_integer()->get()) : v.as_floating_point()->get();
      g.item_rewards.emplace_back(std::stoll(key), reward);
    }
    std::sort(g.item_rewards.begin(), g.item_rewards.end(), [](auto& a, auto& b) { return a.first > b.first; });
  }
  g.win_reward = r.number("win", 1.0, -1e6, 1e6);
  g.lose_reward = r.number("lose", -1.0, -1e6, 1e6);
}

void read_observations(const Reader& root, Integration& g) {
  Reader o = root.table("observations", false);
  o.only({"position", "visual", "local", "audio"});
  Reader p = o.table("position", false);
  p.only({"x", "y", "facing"});
  g.position_x = p.str("x", "");
  g.position_y = p.str("y", "");
  g.position_facing = p.str("facing", "");
  Reader v = o.table("visual", false);
  v.only({"crop", "size"});
  auto crop = v.integers("crop");
  if (!crop.empty()) {
    if (crop.size() != 4 || crop[0] < 0 || crop[1] < 0 || crop[2] < 1 || crop[3] < 1 || crop[0] + crop[2] > 640 ||
        crop[1] + crop[3] > 512)
      v.fail(v.get("crop"), "crop", "expected [x, y, width, height] inside the 640x512 largest display");
    g.visual_x = static_cast<int>(crop[0]), g.visual_y = static_cast<int>(crop[1]);
    g.visual_w = static_cast<int>(crop[2]), g.visual_h = static_cast<int>(crop[3]);
  }
  auto size = v.integers("size");
  if (!size.empty()) {
    if (size.size() != 2 || size[0] < 1 || size[1] < 1 || size[0] > 640 || size[1] > 512)
      v.fail(v.get("size"), "size", "expected [width, height] from 1x1 to 640x512");
    g.visual_out_w = static_cast<int>(size[0]), g.visual_out_h = static_cast<int>(size[1]);
  }
  Reader l = o.table("local", false);
  l.only({"ahead", "behind", "side"});
  g.local_ahead = static_cast<int>(l.integer("ahead", 2, 0, 15));
  g.local_behind = static_cast<int>(l.integer("behind", 0, 0, 15));
  g.local_side = static_cast<int>(l.integer("side", 1, 0, 15));
  Reader a = o.table("audio", false);
  a.only({"frames"});
  g.audio_frames = static_cast<int>(a.integer("frames", 64, 1, 4096));
}

// Every variable the manifest names elsewhere must be declared.
void check_references(const Reader& root, const Integration& g) {
  auto need = [&](const std::string& table, const std::string& key, const std::string& name) {
    if (!name.empty() && !g.find_variable(name)) {
      Reader t = root.table(table, false);
      const toml::node* at = t.get(key);
      t.fail(at, key, "unknown variable '" + name + "' (declare it under [variables])");
    }
  };
  need("boot", "ready", g.boot_ready.variable);
  need("levels", "request_variable", g.request_variable);
  need("levels", "ready", g.level_ready.variable);
  for (const auto& w : g.watch) need("moves", "watch", w);
  need("episode", "state", g.state_variable);
  need("episode", "time", g.time_variable);
  need("reward", "score", g.score_variable);
  Reader obs = root.table("observations", false);
  for (const auto& [key, name] : {std::pair{"x", g.position_x}, {"y", g.position_y}, {"facing", g.position_facing}})
    if (!name.empty() && !g.find_variable(name)) obs.table("position", false).fail(nullptr, key, "unknown variable '" + name + "'");
}

}  // namespace

const Variable* Integration::find_variable(const std::string& n) const {
  for (const auto& v : variables)
    if (v.name == n) return &v;
  return nullptr;
}

const Variable& Integration::variable(const std::string& n) const {
  const Variable* v = find_variable(n);
  if (!v) throw psx::InputError::whole(manifest, "unknown variable '" + n + "'");
  return *v;
}

Integration parse_integration(const std::string& text, const std::string& file, const std::string& folder,
                              const std::string& build_games_dir, const std::string& folder_name) {
  toml::table root_table;
  try {
    root_table = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw psx::InputError::at_line(file, e.source().begin.line, std::string(e.description()));
  }
  Integration g;
  g.manifest = file;
  g.folder = folder;
  Reader root(g.manifest, root_table, "");
  root.only({"name", "title", "script", "script_memory_mib", "boot", "variables", "actions", "levels", "moves",
             "episode", "reward", "observations"});
  g.name = root.str("name", "", true);
  if (!folder_name.empty() && g.name != folder_name)
    root.fail(root.get("name"), "name", "'" + g.name + "' differs from the folder's name '" + folder_name +
                                            "' (a game is chosen by its folder: rename one of them)");
  g.title = root.str("title", g.name);
  std::string script = root.str("script", "");
  if (!script.empty()) {
    if (script.find('/') != std::string::npos || script.find("..") != std::string::npos)
      root.fail(root.get("script"), "script", "expected a file name inside the integration's folder");
    g.script = (fs::path(folder) / script).string();
  }
  g.script_memory_mib = static_cast<std::uint32_t>(root.integer("script_memory_mib", 32, 1, 4096));
  read_boot(root, g, build_games_dir);
  read_variables(root, g);
  read_actions(root, g);
  read_levels(root, g);
  read_moves(root, g);
  read_episode(root, g);
  read_reward(root, g);
  read_observations(root, g);
  check_references(root, g);
  return g;
}

Integration load_integration(const std::string& games_dir, const std::string& name, const std::string& build_games_dir) {
  fs::path folder = fs::path(games_dir) / name;
  fs::path manifest = folder / "game.toml";
  if (name.empty() || name.find('/') != std::string::npos || !fs::exists(manifest)) {
    std::string known;
    for (const auto& n : list_integrations(games_dir)) known += (known.empty() ? "" : ", ") + n;
    // Games come from one folder: PSXRL_GAMES, else the built-in games (or games_dir in Python).
    const char* from_env = std::getenv("PSXRL_GAMES");
    std::string source = from_env && games_dir == from_env ? "PSXRL_GAMES names it"
                         : from_env ? "given as games_dir"
                                    : "PSXRL_GAMES is not set: set it, or games_dir, to the folder holding " + name +
                                          "/game.toml";
    throw psx::InputError("unknown game '" + name + "': no " + manifest.string() + " (games are looked for in " +
                          games_dir + ", which holds " + (known.empty() ? "no games" : known) + "; " + source + ")");
  }
  auto bytes = psx::read_file(manifest.string());
  return parse_integration(std::string(bytes.begin(), bytes.end()), manifest.string(), folder.string(), build_games_dir,
                           name);
}

std::vector<std::string> missing_user_files(const Integration& g, const UserFiles& files, bool needs_states,
                                            bool needs_maps) {
  std::vector<std::string> missing;
  if (g.needs_bios && files.bios.empty() && g.bios.empty())
    missing.push_back("your PlayStation BIOS image: pass --bios FILE (Python: bios=)");
  if (g.user_disc && files.disc.empty()) missing.push_back("your disc image: pass --disc FILE.cue (Python: disc=)");
  if (needs_states && g.level_start == Integration::LevelStart::State &&
      g.state_pattern.find("{states}") != std::string::npos && files.states_dir.empty())
    missing.push_back("your level-start save states: pass --states DIR, the folder to read them from (psxrl play "
                      "saves them there with F5; Python: states=)");
  if (needs_maps && g.map_pattern.find("{maps}") != std::string::npos && files.maps_dir.empty())
    missing.push_back("your level maps, for this observation: pass --maps DIR (Python: maps=)");
  return missing;
}

std::string help_page(const Integration& g) {
  fs::path readme = fs::path(g.folder) / "README.md";
  return fs::exists(readme) ? readme.string() : "docs/integrating-a-game.md, \"Files the user supplies\"";
}

std::string missing_files_message(const Integration& g, const std::vector<std::string>& missing) {
  std::string text = "game '" + g.name + "' needs files you supply (see " + help_page(g) + "):";
  for (const std::string& m : missing) text += "\n  " + m;
  return text;
}

std::string expand(const std::string& pattern, int level, const Integration& game, const UserFiles& files) {
  char two[16];
  std::snprintf(two, sizeof two, "%02d", level);
  const std::pair<std::string, std::string> subs[] = {{"{level:02}", two},
                                                       {"{level}", std::to_string(level)},
                                                       {"{states}", files.states_dir},
                                                       {"{maps}", files.maps_dir},
                                                       {"{folder}", game.folder}};
  // A pattern that does not start with a placeholder is relative to the integration's folder.
  std::string out = pattern.empty() || pattern[0] == '{' || fs::path(pattern).is_absolute()
                        ? pattern
                        : (fs::path(game.folder) / pattern).string();
  for (const auto& [from, to] : subs)
    for (size_t at; (at = out.find(from)) != std::string::npos;) out.replace(at, from.size(), to);
  return out;
}

std::vector<std::string> list_integrations(const std::string& games_dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(games_dir, ec))
    if (entry.is_directory() && fs::exists(entry.path() / "game.toml")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace psxrl::rl
