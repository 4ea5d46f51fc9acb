// Sandboxed Lua 5.4 host (see lua_host.h). Lua is linked statically in its C++ build, so a Lua
// error unwinds C++ frames as an exception and destructors run.
#include "lua/lua_host.h"

#include <lua.hpp>

#include <cstdlib>
#include <stdexcept>

#include "core/input_error.h"

namespace psxrl::lua {

namespace {

// The instruction hook runs every kHookStep VM instructions and counts down the call's budget.
constexpr int kHookStep = 10000;
const char* const kBudgetKey = "psxrl.budget";

void budget_hook(lua_State* L, lua_Debug*) {
  lua_getfield(L, LUA_REGISTRYINDEX, kBudgetKey);
  lua_Integer left = lua_tointeger(L, -1) - kHookStep;
  lua_pop(L, 1);
  lua_pushinteger(L, left);
  lua_setfield(L, LUA_REGISTRYINDEX, kBudgetKey);
  if (left < 0) {
    // luaL_error would name the caller's line (level 1); the loop is the function running here.
    lua_pushfstring(L, "%s the script ran too long (instruction budget exhausted; an endless loop?)",
                    Host::where(L).c_str());
    lua_error(L);
  }
}

int call_function(lua_State* L) {
  auto* fn = static_cast<Host::Function*>(lua_touserdata(L, lua_upvalueindex(1)));
  std::string error;
  try {
    return (*fn)(L);
  } catch (const std::exception& e) {
    error = e.what();
  }
  return luaL_error(L, "%s", error.c_str());
}

// require(name): only plain module names, only from the integration's folder, only source text.
int sandboxed_require(lua_State* L) {
  std::string name = luaL_checkstring(L, 1);
  if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
                          std::string::npos)
    return luaL_error(L, "require('%s'): module names are letters, digits and '_' (files in the integration's folder)",
                      name.c_str());
  std::string path = std::string(lua_tostring(L, lua_upvalueindex(1))) + "/" + name + ".lua";
  int status = luaL_loadfilex(L, path.c_str(), "t");
  if (status == LUA_ERRFILE) return luaL_error(L, "require('%s'): no module file %s", name.c_str(), path.c_str());
  if (status != LUA_OK) return lua_error(L);
  lua_call(L, 0, 1);
  return 1;
}

// load(chunk [, name]): source text only, never precompiled bytecode.
int sandboxed_load(lua_State* L) {
  size_t len = 0;
  const char* text = luaL_checklstring(L, 1, &len);
  const char* name = luaL_optstring(L, 2, "=(load)");
  if (luaL_loadbufferx(L, text, len, name, "t") != LUA_OK) {
    lua_pushnil(L);
    lua_insert(L, -2);
    return 2;
  }
  return 1;
}

}  // namespace

// Lua's allocator contract (lua_Alloc, Lua 5.4 manual 4.6): ptr NULL means old_size is a type
// tag, not a size; new_size 0 frees. Growth past the limit is refused (Lua then raises its memory
// error); shrinking and freeing never fail.
void* Host::allocate(void* ud, void* ptr, std::size_t old_size, std::size_t new_size) {
  auto* m = static_cast<Memory*>(ud);
  if (!ptr) old_size = 0;
  if (new_size == 0) {
    std::free(ptr);
    m->used -= old_size;
    return nullptr;
  }
  if (new_size > old_size && m->used - old_size + new_size > m->limit) {
    // Lua's memory error carries no position, so it is taken now. lua_getinfo's "Sl" reads the
    // call-info list, the running prototype and its saved pc only, which the VM keeps current
    // around everything that allocates (Lua 5.4 lvm.c Protect/savepc, ldo.c growing the stack
    // into a new block before switching to it).
    if (m->L && m->refused_at.empty()) m->refused_at = where(m->L);
    return nullptr;
  }
  void* grown = std::realloc(ptr, new_size);
  if (!grown) return nullptr;
  m->used = m->used - old_size + new_size;
  // Growth after a refusal: Lua collected garbage, tried again and the script goes on.
  if (new_size > old_size && !m->refused_at.empty()) m->refused_at.clear();
  return grown;
}

std::string Host::where(lua_State* L) {
  lua_Debug ar;
  for (int level = 0; lua_getstack(L, level, &ar); ++level) {
    if (!lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0) continue;  // C functions have no line
    const char* file = ar.source[0] == '@' || ar.source[0] == '=' ? ar.source + 1 : ar.short_src;
    return std::string(file) + ":" + std::to_string(ar.currentline) + ":";
  }
  return "";
}

Host::Host(std::string folder, long instruction_budget, std::size_t memory_limit)
    : folder_(std::move(folder)), budget_(instruction_budget) {
  memory_.limit = memory_limit;
  L_ = lua_newstate(&Host::allocate, &memory_);
  if (!L_) throw std::runtime_error("cannot create a Lua state (out of memory)");
  memory_.L = L_;
  const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},      {LUA_TABLIBNAME, luaopen_table},
                           {LUA_STRLIBNAME, luaopen_string}, {LUA_MATHLIBNAME, luaopen_math},
                           {LUA_UTF8LIBNAME, luaopen_utf8}};
  for (const auto& lib : libs) {
    luaL_requiref(L_, lib.name, lib.func, 1);
    lua_pop(L_, 1);
  }
  for (const char* unsafe : {"dofile", "loadfile", "load", "require"}) {
    lua_pushnil(L_);
    lua_setglobal(L_, unsafe);
  }
  lua_pushcfunction(L_, sandboxed_load);
  lua_setglobal(L_, "load");
  lua_pushstring(L_, folder_.c_str());
  lua_pushcclosure(L_, sandboxed_require, 1);
  lua_setglobal(L_, "require");
  lua_sethook(L_, budget_hook, LUA_MASKCOUNT, kHookStep);
}

Host::~Host() {
  if (L_) lua_close(L_);
}

void Host::check(int status, const std::string& what) {
  if (status == LUA_OK) return;
  std::string msg = lua_isstring(L_, -1) ? lua_tostring(L_, -1) : "error object is not a string";
  lua_pop(L_, 1);
  // The allocator's refusal: Lua's own memory error, or lauxlib's buffers, which raise "not
  // enough memory" as an ordinary error.
  if (status == LUA_ERRMEM || (!memory_.refused_at.empty() && msg == "not enough memory")) {
    msg = memory_.refused_at + (memory_.refused_at.empty() ? "" : " ") + "memory limit (" +
          std::to_string(memory_.limit >> 20) + " MiB) exceeded";
    // What the failed call built is garbage now; collect it so the next call starts with room
    // (lauxlib's buffers allocate without Lua's emergency collection).
    lua_gc(L_, LUA_GCCOLLECT);
  }
  memory_.refused_at.clear();
  // Lua's messages start with "file:line:" already; say which step failed after it.
  throw psx::InputError(msg + (what.empty() ? "" : " (in " + what + ")"));
}

void Host::call_prepared(int nargs, int nresults, const std::string& name) {
  memory_.refused_at.clear();
  lua_pushinteger(L_, budget_);
  lua_setfield(L_, LUA_REGISTRYINDEX, kBudgetKey);
  check(lua_pcall(L_, nargs, nresults, 0), name);
}

void Host::run_file(const std::string& path) {
  int status = luaL_loadfilex(L_, path.c_str(), "t");
  if (status == LUA_ERRFILE) {
    lua_pop(L_, 1);
    throw psx::InputError::whole(path, "cannot open file");
  }
  check(status, "");
  call_prepared(0, 0, "");
}

void Host::run_string(const std::string& source, const std::string& name) {
  check(luaL_loadbufferx(L_, source.data(), source.size(), ("@" + name).c_str(), "t"), "");
  call_prepared(0, 0, "");
}

void Host::add_function(const std::string& table, const std::string& name, Function fn) {
  functions_.push_back(std::make_unique<Function>(std::move(fn)));
  if (lua_getglobal(L_, table.c_str()) != LUA_TTABLE) {
    lua_pop(L_, 1);
    lua_newtable(L_);
    lua_pushvalue(L_, -1);
    lua_setglobal(L_, table.c_str());
  }
  lua_pushlightuserdata(L_, functions_.back().get());
  lua_pushcclosure(L_, call_function, 1);
  lua_setfield(L_, -2, name.c_str());
  lua_pop(L_, 1);
}

bool Host::has_function(const std::string& name) const {
  bool is_function = lua_getglobal(L_, name.c_str()) == LUA_TFUNCTION;
  lua_pop(L_, 1);
  return is_function;
}

std::vector<std::optional<double>> Host::call(const std::string& name, const std::vector<double>& args,
                                              int results) {
  lua_getglobal(L_, name.c_str());
  for (double a : args) lua_pushnumber(L_, a);
  call_prepared(static_cast<int>(args.size()), results, name + "()");
  std::vector<std::optional<double>> out(results);
  for (int i = 0; i < results; ++i) {
    int index = -results + i;
    if (lua_isnil(L_, index)) continue;
    if (!lua_isnumber(L_, index)) {
      std::string found = luaL_typename(L_, index);
      lua_pop(L_, results);
      throw psx::InputError(defined_at(name) + name + "(): result " + std::to_string(i + 1) +
                            " must be a number or nil, found a " + found);
    }
    out[i] = lua_tonumber(L_, index);
  }
  lua_pop(L_, results);
  return out;
}

std::optional<std::string> Host::call_string(const std::string& name, const std::vector<double>& args) {
  lua_getglobal(L_, name.c_str());
  for (double a : args) lua_pushnumber(L_, a);
  call_prepared(static_cast<int>(args.size()), 1, name + "()");
  std::optional<std::string> out;
  if (lua_type(L_, -1) == LUA_TSTRING) out = lua_tostring(L_, -1);
  bool bad = !lua_isnil(L_, -1) && !out;
  lua_pop(L_, 1);
  if (bad) throw psx::InputError(defined_at(name) + name + "(): must return a string or nil");
  return out;
}

std::string Host::defined_at(const std::string& name) {
  lua_Debug ar;
  if (lua_getglobal(L_, name.c_str()) != LUA_TFUNCTION) {
    lua_pop(L_, 1);
    return "";
  }
  lua_getinfo(L_, ">S", &ar);  // pops the function
  if (ar.linedefined <= 0) return "";
  const char* file = ar.source[0] == '@' || ar.source[0] == '=' ? ar.source + 1 : ar.short_src;
  return std::string(file) + ":" + std::to_string(ar.linedefined) + ": ";
}

double Host::number_arg(lua_State* L, int index) { return luaL_checknumber(L, index); }

std::string Host::string_arg(lua_State* L, int index) { return luaL_checkstring(L, index); }

}  // namespace psxrl::lua
