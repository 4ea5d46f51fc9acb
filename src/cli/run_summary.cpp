// `psxrl run`'s end-of-run summary, and recognising a game integration's built-in EXE.
#include "cli/run_summary.h"

#include <cstdint>
#include <exception>
#include <optional>

#include "core/input_error.h"
#include "rl/env.h"
#include "rl/integration.h"

namespace psxrl::cli {

namespace {

// The integration whose built-in EXE has exactly these bytes, if any. A broken manifest only
// means that game cannot be recognised: the run itself is over and succeeded.
std::optional<rl::Integration> integration_for(const std::vector<psx::u8>& exe) {
  const std::string games = rl::default_games_dir(), built = rl::default_build_games_dir();
  for (const std::string& name : rl::list_integrations(games)) {
    try {
      rl::Integration g = rl::load_integration(games, name, built);
      if (!g.exe.empty() && psx::read_file(g.exe) == exe) return g;
    } catch (const std::exception&) {
    }
  }
  return std::nullopt;
}

std::int64_t read_variable(const psx::Console& c, const rl::Variable& v) {
  switch (v.type) {
    case rl::Variable::Type::U8: return c.read8(v.address);
    case rl::Variable::Type::S8: return static_cast<std::int8_t>(c.read8(v.address));
    case rl::Variable::Type::U16: return c.read16(v.address);
    case rl::Variable::Type::S16: return static_cast<std::int16_t>(c.read16(v.address));
    case rl::Variable::Type::U32: return c.read32(v.address);
    case rl::Variable::Type::S32: return static_cast<std::int32_t>(c.read32(v.address));
  }
  return 0;
}

// "GAME: level L, score S, outcome O": outcome as the environments name it (win, lose) from the
// integration's episode states, "none" while the episode goes on; level from a variable named
// "level" when the integration has one.
void print_game(std::FILE* out, const psx::Console& c, const rl::Integration& g) {
  std::string line = "psxrl run: " + g.name + ":";
  if (const rl::Variable* level = g.find_variable("level"))
    line += " level " + std::to_string(read_variable(c, *level)) + ",";
  if (!g.score_variable.empty())
    line += " score " + std::to_string(read_variable(c, g.variable(g.score_variable))) + ",";
  std::string outcome = "none";
  if (!g.state_variable.empty()) {
    const std::int64_t state = read_variable(c, g.variable(g.state_variable));
    if (rl::contains_value(g.win_states, state)) outcome = "win";
    else if (rl::contains_value(g.lose_states, state)) outcome = "lose";
    outcome += " (state " + std::to_string(state) + ")";
  }
  std::fprintf(out, "%s outcome %s\n", line.c_str(), outcome.c_str());
}

}  // namespace

void print_run_summary(std::FILE* out, const psx::Console& console, const std::string& exe,
                       const std::vector<std::string>& written) {
  std::fprintf(out, "psxrl run: %llu frames\n", static_cast<unsigned long long>(console.frames()));
  for (const std::string& file : written) std::fprintf(out, "psxrl run: wrote %s\n", file.c_str());
  if (console.cpu_mode() == psx::Console::CpuMode::Recompiler) {
    const auto& r = console.recompiler_stats();
    std::fprintf(out, "psxrl run: recompiler: %llu blocks compiled, %llu invalidations, %llu code-buffer flushes\n",
                 static_cast<unsigned long long>(r.compiled), static_cast<unsigned long long>(r.invalidated),
                 static_cast<unsigned long long>(r.flushes));
  }
  if (exe.empty()) return;
  std::vector<psx::u8> bytes;
  try {
    bytes = psx::read_file(exe);
  } catch (const psx::InputError&) {
    return;  // booted moments ago; if it is gone now, there is just no game line
  }
  if (auto game = integration_for(bytes)) print_game(out, console, *game);
}

}  // namespace psxrl::cli
