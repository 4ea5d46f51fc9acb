// The integration scripting host (src/lua/lua_host.h): the sandbox holds (no os, io, file loading
// or bytecode), require stays inside the integration's folder, errors carry file:line, and an
// endless loop is stopped by the instruction budget instead of hanging.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "lua/lua_host.h"

using psxrl::lua::Host;

namespace {

std::string error_of(Host& h, const std::string& code) {
  try {
    h.run_string(code, "t.lua");
  } catch (const psx::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LuaHost, CallsFunctionsWithNumbers) {
  Host h(".");
  h.run_string("function add(a, b) return a + b, a * b end\nfunction name() return 'x' end", "t.lua");
  auto r = h.call("add", {2, 5}, 2);
  EXPECT_EQ(r[0], 7.0);
  EXPECT_EQ(r[1], 10.0);
  EXPECT_TRUE(h.has_function("add"));
  EXPECT_FALSE(h.has_function("sub"));
  EXPECT_EQ(h.call_string("name", {}), "x");
}

TEST(LuaHost, SandboxHasNoOsIoDebugOrFileLoading) {
  Host h(".");
  EXPECT_EQ(error_of(h, "assert(os == nil and io == nil and debug == nil and package == nil and dofile == nil and loadfile == nil)"), "");
  EXPECT_EQ(error_of(h, "assert(string.format('%d', 3) == '3' and math.floor(2.5) == 2 and table.concat({1,2}) == '12')"), "");
}

TEST(LuaHost, LoadTakesTextButNeverBytecode) {
  Host h(".");
  EXPECT_EQ(error_of(h, "assert(load('return 1 + 1')() == 2)"), "");
  // A precompiled chunk starts with ESC 'Lua'; load() must refuse it.
  EXPECT_EQ(error_of(h, "local f, err = load('\\27Lua') assert(f == nil and err:find('binary'))"), "");
}

TEST(LuaHost, RequireReadsOnlyTheIntegrationsFolder) {
  auto dir = std::filesystem::temp_directory_path() / "psxrl_lua_host_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "helper.lua") << "return { answer = 42 }\n";
  Host h(dir.string());
  EXPECT_EQ(error_of(h, "assert(require('helper').answer == 42)"), "");
  EXPECT_NE(error_of(h, "require('../etc/passwd')").find("module names are letters, digits and '_'"), std::string::npos);
  EXPECT_NE(error_of(h, "require('missing')").find("missing.lua"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(LuaHost, ErrorsCarryFileAndLine) {
  Host h(".");
  EXPECT_EQ(error_of(h, "local x = 1\nx = x +\n"), "t.lua:3: unexpected symbol near <eof>");
  EXPECT_EQ(error_of(h, "local t = nil\n\nlocal y = t.field\n").rfind("t.lua:3: attempt to index a nil value", 0), 0u);
  h.run_string("function boom()\n  error('bad move')\nend", "g.lua");
  try {
    h.call("boom", {}, 0);
    FAIL();
  } catch (const psx::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "g.lua:2: bad move (in boom())");
  }
}

TEST(LuaHost, EndlessLoopsRunOutOfBudget) {
  Host h(".", 1'000'000);
  EXPECT_NE(error_of(h, "while true do end").find("instruction budget exhausted"), std::string::npos);
  // The budget is per call: the host is usable afterwards.
  EXPECT_EQ(error_of(h, "local s = 0 for i = 1, 1000 do s = s + i end assert(s == 500500)"), "");
}

TEST(LuaHost, CppFunctionsReportErrorsAtTheCallingLine) {
  Host h(".");
  h.add_function("env", "twice", [](lua_State* L) {
    double v = Host::number_arg(L, 1);
    if (v < 0) throw std::invalid_argument("twice: expected a positive number");
    return 0;
  });
  EXPECT_EQ(error_of(h, "env.twice(2)"), "");
  EXPECT_EQ(error_of(h, "\nenv.twice(-1)"), "t.lua:2: twice: expected a positive number");
}
