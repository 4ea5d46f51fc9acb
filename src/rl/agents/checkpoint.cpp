// Checkpoint files (see checkpoint.h): magic, format, payload length and FNV-1a checksum, then the
// settings, the agent's bytes and the trainer's bytes.
#include "rl/agents/checkpoint.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "core/hash.h"
#include "rl/agents/serialize.h"

namespace psxrl::agents {

namespace {

constexpr char kMagic[8] = {'P', 'S', 'X', 'R', 'L', 'C', 'K', 'P'};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

}  // namespace

std::string format_double(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  ByteWriter payload;
  payload.u64(c.meta.size());
  for (const auto& [k, v] : c.meta) {
    payload.str(k);
    payload.str(v);
  }
  payload.str(c.agent);
  payload.str(c.trainer);
  const auto& body = payload.bytes();
  ByteWriter head;
  head.u64(kCheckpointFormat);
  head.u64(body.size());
  head.u64(psx::fnv1a(body.data(), body.size()));
  std::vector<psx::u8> file(kMagic, kMagic + sizeof kMagic);
  file.insert(file.end(), head.bytes().begin(), head.bytes().end());
  file.insert(file.end(), body.begin(), body.end());
  psx::write_file_atomically(path, file);
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw CorruptCheckpoint(path + ": cannot open file");
  std::string data = slurp(path);
  if (data.size() < sizeof kMagic + 24 || data.compare(0, sizeof kMagic, kMagic, sizeof kMagic) != 0)
    throw CorruptCheckpoint(path + ": not a psxrl checkpoint (expected the magic PSXRLCKP and a header)");
  ByteReader head(data.data() + sizeof kMagic, 24, path);
  std::uint64_t format = head.u64(), size = head.u64(), sum = head.u64();
  if (format != kCheckpointFormat)
    throw CorruptCheckpoint(path + ": checkpoint format " + std::to_string(format) + ", this psxrl reads format " +
                            std::to_string(kCheckpointFormat));
  const char* body = data.data() + sizeof kMagic + 24;
  size_t have = data.size() - sizeof kMagic - 24;
  if (have != size)
    throw CorruptCheckpoint(path + ": truncated or padded: the header says " + std::to_string(size) +
                            " bytes of payload, the file has " + std::to_string(have));
  if (psx::fnv1a(body, have) != sum) throw CorruptCheckpoint(path + ": checksum mismatch (the file is corrupt)");
  ByteReader r(body, have, path);
  Checkpoint c;
  std::uint64_t n = r.count(16);
  for (std::uint64_t i = 0; i < n; ++i) {
    std::string k = r.str();
    c.meta[k] = r.str();
  }
  c.agent = r.str();
  c.trainer = r.str();
  if (!r.done()) r.fail("unexpected bytes after the trainer state");
  return c;
}

std::string checkpoint_path(const std::string& run_or_file) {
  if (std::filesystem::is_directory(run_or_file)) return (std::filesystem::path(run_or_file) / kCheckpointFile).string();
  return run_or_file;
}

std::string integration_hash(const rl::Integration& game) {
  std::string text = slurp(game.manifest);
  if (!game.script.empty()) text += slurp(game.script);
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(psx::fnv1a(text.data(), text.size())));
  return buf;
}

std::string policy_mismatch(const Settings& meta, const std::string& game, const std::string& obs,
                            const std::string& hash, const std::string& network) {
  auto get = [&](const char* k) {
    auto it = meta.find(k);
    return it == meta.end() ? std::string("(none)") : it->second;
  };
  if (get("game") != game) return "it was trained for game '" + get("game") + "', not '" + game + "'";
  if (get("obs") != obs) return "it was trained on the '" + get("obs") + "' observation, not '" + obs + "'";
  if (get("integration_hash") != hash)
    return "it was trained against another version of the '" + game + "' integration (hash " +
           get("integration_hash") + ", now " + hash + ")";
  if (get("network") != network)
    return "its network is '" + get("network") + "', this agent and observation make '" + network + "'";
  return "";
}

}  // namespace psxrl::agents
