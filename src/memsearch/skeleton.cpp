// Integration skeletons from found variables (skeleton.h).
#include "memsearch/skeleton.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "core/atomic_file.h"

namespace psxrl::memsearch {

namespace {

bool valid_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

const FoundVariable* find(const std::vector<FoundVariable>& vars, const std::string& name) {
  for (const FoundVariable& v : vars)
    if (v.name == name) return &v;
  return nullptr;
}

}  // namespace

FoundVariable parse_found_variable(const std::string& text) {
  size_t eq = text.find('='), colon = text.rfind(':');
  if (eq == std::string::npos || colon == std::string::npos || colon < eq)
    throw QueryError("'" + text + "': expected NAME=ADDRESS:ENCODING, e.g. score=0x8001000C:u32");
  FoundVariable v;
  v.name = text.substr(0, eq);
  if (!valid_name(v.name)) throw QueryError("'" + text + "': a variable name is letters, digits and _");
  try {
    size_t used = 0;
    unsigned long a = std::stoul(text.substr(eq + 1, colon - eq - 1), &used, 0);
    if (used != colon - eq - 1 || a > 0xFFFFFFFFul) throw std::out_of_range(text);
    v.address = static_cast<psx::u32>(a);
  } catch (const std::exception&) {
    throw QueryError("'" + text + "': the address must be a number such as 0x8001000C");
  }
  if (!parse_encoding(text.substr(colon + 1), v.encoding))
    throw QueryError("'" + text + "': unknown encoding '" + text.substr(colon + 1) + "'");
  return v;
}

std::string integration_skeleton(const std::string& name, const SessionSource& source,
                                 const std::vector<FoundVariable>& vars) {
  if (!valid_name(name)) throw QueryError("integration name '" + name + "': use letters, digits and _");
  if (vars.empty()) throw QueryError("an integration needs at least one variable");
  std::ostringstream t;
  t << "# " << name << ": integration skeleton written by psxrl memsearch from a recorded session.\n"
    << "# Variables are what the search found; the rest are the seed's defaults to edit\n"
    << "# (docs/integrating-a-game.md).\n"
    << "name = " << quoted(name) << "\n\n[boot]\n";
  if (!source.exe.empty()) t << "exe = " << quoted(source.exe) << "\n";
  else t << "disc = \"user\"       # --disc FILE.cue\n";
  if (!source.bios.empty()) t << "bios = \"user\"       # --bios FILE\n";
  t << "\n[variables]\n";
  for (const FoundVariable& v : vars) {
    psx::u32 offset = 0;
    int e = static_cast<int>(v.encoding);
    bool little = e <= static_cast<int>(Encoding::S8);
    if (!little || !address_to_offset(v.address, offset) || offset >= kRamBytes)
      throw QueryError("variable '" + v.name + "' (" + encoding_name(v.encoding) +
                       "): the manifest reads little-endian words in main RAM; read it with env.raw() in game.lua");
    if (offset % encoding_size(v.encoding) != 0) throw QueryError("variable '" + v.name + "': address is not aligned");
    char addr[16];
    std::snprintf(addr, sizeof addr, "0x%08X", kRamBase + offset);
    t << v.name << " = { address = " << addr << ", type = \"" << encoding_name(v.encoding) << "\" }\n";
  }
  const char* actions[][2] = {{"FORWARD", "up"}, {"LOOKRIGHT", "right"}, {"LOOKLEFT", "left"}, {"JUMPFORWARD", "cross"}};
  t << "\n# The seed's four actions; change the buttons to the game's controls. In each frame-skip step\n"
    << "# the buttons are down for `hold` frames, then up for the rest of the step, so a game that acts\n"
    << "# on presses sees one press per step; hold >= frame_skip keeps them down across steps.\n";
  for (const auto& a : actions) t << "[[actions]]\nname = \"" << a[0] << "\"\nbuttons = [\"" << a[1] << "\"]\nhold = 3\n\n";
  const FoundVariable* state = find(vars, "state");
  t << "# Levels start from save states you make with psxrl play (F5 at a level's start).\n"
    << "[levels]\ncount = 1\nstart = \"state\"\nstate = \"{states}/level{level:02}.state\"\n\n"
    << "# Fixed frame skip until the watched variables for the seed's delimiter are chosen.\n"
    << "[moves]\nmode = \"frames\"\nframe_skip = [4]\n\n"
    << "[episode]\nstate = " << quoted(state ? state->name : vars.front().name)
    << (state ? "\n" : "   # no variable named 'state' was found: name the game-state word\n")
    << "win = []\nlose = []\n";
  if (const FoundVariable* score = find(vars, "score")) t << "\n[reward]\nscore = " << quoted(score->name) << "\n";
  return t.str();
}

void write_integration_skeleton(const std::string& dir, const std::string& name, const SessionSource& source,
                                const std::vector<FoundVariable>& vars) {
  std::string text = integration_skeleton(name, source, vars);
  std::string manifest = dir + "/game.toml";
  if (std::filesystem::exists(manifest)) throw QueryError(manifest + " already exists: not overwritten");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create the folder (" + ec.message() + ")");
  psx::write_file_atomically(manifest, std::vector<psx::u8>(text.begin(), text.end()));
}

}  // namespace psxrl::memsearch
