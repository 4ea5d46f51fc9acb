// `psxrl sweep CONFIG.toml [--address HOST:PORT] [--out DIR]`: a grid of `psxrl train` runs on Ray,
// and `psxrl experiment NAME [--tiny]`, one of the seed's studies run as such a sweep.
// Both are Python (psxrl.ray, docs/scaling.md; psxrl.experiments, docs/results.md), so this process
// becomes that Python: the
// interpreter in $PSXRL_PYTHON (default python3), with this executable as the runs' trainer and,
// from a build tree, the build's module on its path.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli.h"

namespace psxrl::cli {

namespace {

// A build tree holds the module in build/python beside build/psxrl (src/python/CMakeLists.txt).
void use_this_build(const std::filesystem::path& self) {
  setenv("PSXRL_EXE", self.c_str(), 0);  // an explicit PSXRL_EXE wins
  std::filesystem::path module = self.parent_path() / "python";
  std::error_code ec;
  if (!std::filesystem::is_directory(module / "psxrl", ec)) return;
  std::string path = module.string();
  if (const char* had = std::getenv("PYTHONPATH"); had && *had) path += std::string(":") + had;
  setenv("PYTHONPATH", path.c_str(), 1);
}

// Replaces this process with `$PSXRL_PYTHON WORDS... ARGS...` (WORDS: -m and the module); returns
// only on failure.
int run_python_module(const char* command, std::vector<std::string> words, const std::vector<std::string>& args) {
  std::error_code ec;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) use_this_build(self);
  const char* python = std::getenv("PSXRL_PYTHON");
  if (python == nullptr || *python == '\0') python = "python3";
  words.insert(words.begin(), python);
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  execvp(python, argv.data());
  std::fprintf(stderr, "psxrl %s: cannot run %s (%s): set PSXRL_PYTHON to a Python with psxrl and Ray\n", command,
               python, std::strerror(errno));
  return kUsage;
}

}  // namespace

int sweep_command(const std::vector<std::string>& args) {
  return run_python_module("sweep", {"-m", "psxrl.ray", "sweep"}, args);
}

int experiment_command(const std::vector<std::string>& args) {
  return run_python_module("experiment", {"-m", "psxrl.experiments"}, args);
}

}  // namespace psxrl::cli
