// Shared pieces of the psxrl command line: exit codes and the subcommand entry points.
#pragma once
#include <string>
#include <vector>

namespace psxrl::cli {

// Exit codes of `psxrl` (DESIGN.md "Exit codes"); a program run by `psxrl run` may also exit with
// its own code through the debug port.
enum ExitCode : int {
  kSuccess = 0,
  kUsage = 1,
  kBadInput = 2,
  kProgramFailed = 3,
};

int run_command(const std::vector<std::string>& args);
int train_command(const std::vector<std::string>& args);
int play_command(const std::vector<std::string>& args);
int record_command(const std::vector<std::string>& args);
int memsearch_command(const std::vector<std::string>& args);
int sweep_command(const std::vector<std::string>& args);
int compat_command(const std::vector<std::string>& args);
// `psxrl experiment NAME`: one of the seed's studies, a sweep run by psxrl.experiments (docs/results.md).
int experiment_command(const std::vector<std::string>& args);

}  // namespace psxrl::cli
