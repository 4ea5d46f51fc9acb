// The scripting host for game integrations: one sandboxed Lua 5.4 state per environment (never
// shared across threads). Scripts get the base, string, table, math and utf8 libraries only: no
// os, io, debug, bytecode loading or file access, and `require` reads only `<name>.lua` from the
// integration's own folder. Every call has an instruction budget, so a script that loops forever
// fails with a message instead of hanging the environment, and every state has a memory limit
// (an allocator that refuses past it), so a script that allocates without end fails the same way
// instead of taking the host's memory. Script errors become psx::InputError
// carrying Lua's own "file:line: message", so front ends report them like any bad input file.
#pragma once
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct lua_State;

namespace psxrl::lua {

class Host {
 public:
  // A C++ function callable from Lua as `table.name(...)`. It reads its arguments from the stack
  // (the helpers below) and returns how many results it pushed. Throwing std::exception turns
  // into a Lua error at the calling line.
  using Function = std::function<int(lua_State*)>;

  static constexpr long kDefaultBudget = 50'000'000;                 // VM instructions per call
  static constexpr std::size_t kDefaultMemoryLimit = 32u << 20;  // bytes; a manifest may change it

  // `folder` is where `require` looks; the instruction budget is per call from C++; the memory
  // limit is the most the state may hold at once, in bytes.
  explicit Host(std::string folder, long instruction_budget = kDefaultBudget,
                std::size_t memory_limit = kDefaultMemoryLimit);
  ~Host();
  Host(const Host&) = delete;
  Host& operator=(const Host&) = delete;

  // Loads and runs a script file (its top level defines the integration's functions).
  void run_file(const std::string& path);
  // Runs a chunk of source text named `name` (for tests and one-line expressions).
  void run_string(const std::string& source, const std::string& name);

  // Registers `table.name` as a C++ function (the table is created on first use).
  void add_function(const std::string& table, const std::string& name, Function fn);

  bool has_function(const std::string& name) const;
  // Calls global function `name` with numeric arguments and returns up to `results` values;
  // nil results are std::nullopt, strings are returned through call_string.
  std::vector<std::optional<double>> call(const std::string& name, const std::vector<double>& args, int results);
  // Calls global function `name` and returns its first result if it is a string.
  std::optional<std::string> call_string(const std::string& name, const std::vector<double>& args);

  lua_State* state() { return L_; }

  // Argument helpers for Functions: a clear Lua error names the argument when it is wrong.
  static double number_arg(lua_State* L, int index);
  static std::string string_arg(lua_State* L, int index);
  // "file:line:" of the innermost Lua function running (the script's line, not a C caller's).
  static std::string where(lua_State* L);

 private:
  void call_prepared(int nargs, int nresults, const std::string& name);
  void check(int status, const std::string& what);
  // "file:line: " where global function `name` is defined ("" when it is not a Lua function).
  std::string defined_at(const std::string& name);

  // What the allocator counts (lua_host.cpp): bytes held, the limit, and where the script was
  // when it refused (Lua's own out-of-memory error carries no position).
  struct Memory {
    std::size_t used = 0, limit = 0;
    lua_State* L = nullptr;
    std::string refused_at;
  };
  static void* allocate(void* ud, void* ptr, std::size_t old_size, std::size_t new_size);

  Memory memory_;
  lua_State* L_ = nullptr;
  std::string folder_;
  long budget_;
  std::vector<std::unique_ptr<Function>> functions_;
};

}  // namespace psxrl::lua
