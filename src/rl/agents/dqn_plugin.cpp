// make_dqn_agent: loads the DQN agent's plugin, libpsxrl_dqn.so, the first time a DQN agent is
// made (dqn_agent.h says why it is a plugin). The plugin resolves the agent interface's symbols
// from the executable that loads it, which exports them (CMake ENABLE_EXPORTS).
#include <dlfcn.h>
#include <unistd.h>

#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "rl/agents/dqn_agent.h"

#ifndef PSXRL_PLUGIN_DIR
#error "PSXRL_PLUGIN_DIR must name the build folder that holds libpsxrl_dqn.so"
#endif

namespace psxrl::agents {

namespace {

// The folder of the running executable: a plugin beside it wins over the build folder's, so a
// copied build finds its own.
std::string executable_dir() {
  char path[4096];
  ssize_t n = readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (n <= 0) return {};
  std::string p(path, static_cast<size_t>(n));
  size_t slash = p.rfind('/');
  return slash == std::string::npos ? std::string() : p.substr(0, slash);
}

bool same_stamp(const DqnPluginStamp& a, const DqnPluginStamp& b) {
  return std::strcmp(a.version, b.version) == 0 && a.agent_options == b.agent_options && a.space == b.space &&
         a.agent == b.agent;
}

// Opens the first plugin that loads and matches this build, else throws with what each place
// said. The handle is never closed: the agents it makes live until the process ends.
DqnFactoryFn open_plugin() {
  std::vector<std::string> dirs{PSXRL_PLUGIN_DIR};
  if (std::string beside = executable_dir(); !beside.empty() && beside != dirs[0]) dirs.insert(dirs.begin(), beside);
  std::string tried;
  for (const std::string& dir : dirs) {
    std::string file = dir + "/" + kDqnPluginFile;
    if (access(file.c_str(), F_OK) != 0) {
      tried += "\n  " + file + ": no such file";
      continue;
    }
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      tried += "\n  " + file + ": " + dlerror();
      continue;
    }
    auto stamp = reinterpret_cast<DqnStampFn>(dlsym(handle, kDqnStampSymbol));
    auto factory = reinterpret_cast<DqnFactoryFn>(dlsym(handle, kDqnFactorySymbol));
    constexpr DqnPluginStamp kOurs = dqn_plugin_stamp();
    if (stamp == nullptr || factory == nullptr || !same_stamp(*stamp(), kOurs)) {
      tried += "\n  " + file + ": built by another psxrl (expected release " + kOurs.version + " of this build)";
      dlclose(handle);
      continue;
    }
    return factory;
  }
  throw std::runtime_error(std::string("the dqn agent needs its LibTorch plugin ") + kDqnPluginFile +
                           ", which did not load (build it with `cmake --build build`):" + tried);
}

DqnFactoryFn plugin_factory() {
  static std::once_flag once;
  static DqnFactoryFn factory = nullptr;
  std::call_once(once, [] { factory = open_plugin(); });
  return factory;
}

}  // namespace

std::unique_ptr<Agent> make_dqn_agent(const std::vector<rl::Space>& spaces, bool interpret, int actions,
                                      const AgentOptions& options) {
  return std::unique_ptr<Agent>(plugin_factory()(spaces, interpret, actions, options));
}

std::unique_ptr<Agent> make_dqn_agent(int inputs, int actions, const AgentOptions& options) {
  return make_dqn_agent({rl::Space{"features", {inputs}, rl::DType::F32, 0, 0}}, false, actions, options);
}

}  // namespace psxrl::agents
