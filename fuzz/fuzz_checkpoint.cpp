// Fuzzes policy checkpoints (src/rl/agents/checkpoint.h): any file either reads back as a
// checkpoint whose settings can be checked against a game, or is refused with CorruptCheckpoint.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "rl/agents/checkpoint.h"
#include "rl/agents/serialize.h"

namespace ag = psxrl::agents;

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  static const std::string path =
      (std::filesystem::temp_directory_path() / ("psxrl_fuzz_checkpoint_" + std::to_string(getpid()))).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), size);
  try {
    ag::Checkpoint c = ag::read_checkpoint(path);
    ag::policy_mismatch(c.meta, "tumble", "simple", "0", "none");
  } catch (const ag::CorruptCheckpoint&) {
  }
  return 0;
}
