// Checkpoints and saved policies: one file holding the run's settings (game, observation, agent,
// network, options), the psxrl version, the integration's hash, the agent's whole learning state
// and the trainer's. Written atomically; read back with every byte checked, so a truncated or
// corrupt file is refused with a message instead of loading half a policy.
#pragma once
#include <cstdint>
#include <map>
#include <string>

#include "rl/integration.h"

namespace psxrl::agents {

inline constexpr std::uint64_t kCheckpointFormat = 1;
inline constexpr const char* kPsxrlVersion = PSXRL_VERSION;  // project(VERSION) in CMakeLists.txt
inline constexpr const char* kCheckpointFile = "checkpoint.psxrl";

using Settings = std::map<std::string, std::string>;

struct Checkpoint {
  Settings meta;        // settings plus format, psxrl_version, integration_hash, network
  std::string agent;    // Agent::save()
  std::string trainer;  // the trainer's episode counter and metrics
};

// Throws std::runtime_error naming the file when it cannot be written.
void write_checkpoint(const std::string& path, const Checkpoint& c);
// Throws CorruptCheckpoint (serialize.h) for a missing, truncated, corrupt or foreign file.
Checkpoint read_checkpoint(const std::string& path);
// A run folder names its checkpoint file; a file names itself.
std::string checkpoint_path(const std::string& run_or_file);

// FNV-1a over the integration's manifest and script: a policy learnt against one version of a
// game's rewards, actions and levels is not silently used with another.
std::string integration_hash(const rl::Integration& game);

// Why a saved policy cannot drive `game` through observation `obs` with `network`, or "" when
// it can.
std::string policy_mismatch(const Settings& meta, const std::string& game, const std::string& obs,
                            const std::string& integration_hash, const std::string& network);

std::string format_double(double v);  // shortest text that reads back to the same double

}  // namespace psxrl::agents
