// Runs every case of the SingleStepTests r3000 data (tests/data/r3000-singlestep, format in its
// README): one instruction from a recorded state against a scripted bus, then compares
// registers, HI/LO, PC, EPC, the pending branch and load, Cause (ExcCode, BD) and data writes.
// Every case runs twice: stepped by the interpreter, and from a block of the recompiler.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/cpu/cpu_impl.h"
#include "testdata.h"

namespace psx {
namespace {

struct StepState {
  u32 r[32], hi, lo, epc, tar, cause, pc;
  u32 branch_target, in_delay_slot, branch_taken;
  s32 load_reg;
  u32 load_value;
};
static_assert(sizeof(StepState) == 172);  // the layout the data has (the README rounds it to 176)

struct BusRecord {
  s64 value;
  u32 action;
  s64 address;
  u32 size;
};

struct StepCase {
  std::string name;
  u32 opcode, opcode_addr;
  StepState initial, final;
  std::vector<BusRecord> cycles;
};

std::vector<StepCase> read_cases(const std::filesystem::path& file) {
  const std::string d = test::read_gz(file);
  std::vector<StepCase> out;
  size_t o = 0;
  auto take = [&](void* p, size_t n) {
    if (o + n > d.size()) throw std::runtime_error(file.string() + ": truncated at offset " + std::to_string(o));
    std::memcpy(p, &d[o], n);
    o += n;
  };
  s32 count;
  take(&count, 4);
  for (s32 i = 0; i < count; ++i) {
    StepCase c;
    u8 name[51];
    take(name, 51);
    c.name.assign(reinterpret_cast<char*>(name + 1), name[0]);
    take(&c.opcode, 4);
    take(&c.opcode_addr, 4);
    take(&c.initial, sizeof(StepState));
    take(&c.final, sizeof(StepState));
    u32 n;
    take(&n, 4);
    c.cycles.resize(n);
    for (auto& r : c.cycles) {
      take(&r.value, 8);
      take(&r.action, 4);
      take(&r.address, 8);
      take(&r.size, 4);
    }
    out.push_back(std::move(c));
  }
  return out;
}

// Answers fetches and reads from the case's recorded bus activity and records the writes. The
// data records each access at its byte address with its size in bytes (partial-word LWL/LWR/
// SWL/SWR accesses cover just the bytes they use), so reads and writes are compared byte by byte.
class ScriptBus {
 public:
  explicit ScriptBus(const StepCase& c) : case_(c) {
    for (const BusRecord& r : c.cycles)
      if (r.action == 1)
        for (u32 i = 0; i < r.size; ++i) memory_[u32(r.address) + i] = u8(u64(r.value) >> (8 * i));
  }
  bool fetch(u32 addr, u32& v) {
    v = addr == case_.opcode_addr ? case_.opcode : 0;
    return true;
  }
  bool peek_code(u32 addr, u32& v) const {  // what the recompiler compiles from
    v = addr == case_.opcode_addr ? case_.opcode : 0;
    return true;
  }
  bool read32(u32 a, u32& v) { return read(a, v, 4); }
  bool read16(u32 a, u32& v) { return read(a, v, 2); }
  bool read8(u32 a, u32& v) { return read(a, v, 1); }
  bool write32(u32 a, u32 v) { return write(a, v, 4); }
  bool write16(u32 a, u32 v) { return write(a, v, 2); }
  bool write8(u32 a, u32 v) { return write(a, v, 1); }
  void isolated_store(u32, u32) {}  // the recorded cases never isolate the cache

  std::map<u32, u8> written;

 private:
  bool read(u32 addr, u32& v, u32 size) {
    v = 0;
    for (u32 i = 0; i < size; ++i) {
      auto it = memory_.find(addr + i);
      if (it != memory_.end()) v |= u32(it->second) << (8 * i);
    }
    return true;
  }
  bool write(u32 addr, u32 v, u32 size) {
    for (u32 i = 0; i < size; ++i) written[addr + i] = u8(v >> (8 * i));
    return true;
  }
  const StepCase& case_;
  std::map<u32, u8> memory_;
};

std::string hex(u32 v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", v);
  return b;
}

// Compares one case; returns a description of the first difference, or "" when it matches.
std::string run_case(const StepCase& c, bool recompiled) {
  Scheduler sched;
  InterruptController irq;
  Gte gte;
  ScriptBus bus(c);
  CpuT<ScriptBus> cpu(bus, sched, irq, gte);
  const StepState& in = c.initial;
  for (u32 r = 1; r < 32; ++r) cpu.set_reg(r, in.r[r]);
  cpu.set_hi(in.hi);
  cpu.set_lo(in.lo);
  cpu.set_pc(in.pc);
  cpu.cop0().sr = 0;  // not recorded; the data's exceptions vector to 0x80000080 (BEV = 0)
  cpu.cop0().epc = in.epc;
  cpu.cop0().cause = in.cause & ~0x300u;  // no software interrupt may fire
  CpuT<ScriptBus>::Pending p;
  p.in_delay_slot = in.in_delay_slot != 0;
  p.next_pc = in.in_delay_slot && in.branch_taken ? in.branch_target : in.pc + 4;
  p.load_reg = in.load_reg < 0 ? 0 : u32(in.load_reg);
  p.load_value = in.load_value;
  cpu.set_pending(p);

  if (recompiled) {
    // run() goes on until the next event: one booked a cycle ahead stops it after one instruction.
    RecompilerT<ScriptBus> rec(bus);
    cpu.set_recompiler(&rec);
    sched.schedule(sched.add_event("stop", [](Cycles) {}), 1);
    cpu.run();
  } else {
    cpu.step();
  }

  const StepState& want = c.final;
  std::ostringstream diff;
  for (u32 r = 1; r < 32; ++r)
    if (cpu.reg(r) != want.r[r]) diff << "r" << r << " " << hex(cpu.reg(r)) << " want " << hex(want.r[r]) << "; ";
  if (cpu.hi() != want.hi) diff << "hi " << hex(cpu.hi()) << " want " << hex(want.hi) << "; ";
  if (cpu.lo() != want.lo) diff << "lo " << hex(cpu.lo()) << " want " << hex(want.lo) << "; ";
  if (cpu.pc() != want.pc) diff << "pc " << hex(cpu.pc()) << " want " << hex(want.pc) << "; ";
  if (cpu.cop0().epc != want.epc) diff << "epc " << hex(cpu.cop0().epc) << " want " << hex(want.epc) << "; ";
  const u32 cause_mask = 0x8000007C;
  if ((cpu.cop0().cause & cause_mask) != (want.cause & cause_mask))
    diff << "cause " << hex(cpu.cop0().cause) << " want " << hex(want.cause) << "; ";
  auto got = cpu.pending();
  if (got.in_delay_slot != (want.in_delay_slot != 0)) diff << "delay-slot flag differs; ";
  if (want.in_delay_slot && want.branch_taken && got.next_pc != want.branch_target)
    diff << "branch target " << hex(got.next_pc) << " want " << hex(want.branch_target) << "; ";
  u32 want_load = want.load_reg < 0 ? 0 : u32(want.load_reg);
  if (got.load_reg != want_load || (want_load && got.load_value != want.load_value))
    diff << "pending load r" << got.load_reg << "=" << hex(got.load_value) << " want r" << want_load << "="
         << hex(want.load_value) << "; ";
  std::map<u32, u8> want_writes;
  for (const BusRecord& r : c.cycles)
    if (r.action == 2)
      for (u32 i = 0; i < r.size; ++i) want_writes[u32(r.address) + i] = u8(u64(r.value) >> (8 * i));
  if (bus.written != want_writes)
    diff << "data writes differ (" << bus.written.size() << " bytes vs " << want_writes.size() << "); ";
  return diff.str();
}

class SingleStep : public ::testing::TestWithParam<std::string> {};

void check_all_cases(const std::string& instruction, bool recompiled) {
  const auto file = test::testdata_dir() / "r3000-singlestep" / (instruction + ".json.bin.gz");
  std::vector<StepCase> cases;
  try {
    cases = read_cases(file);
  } catch (const std::exception& e) {
    FAIL() << e.what();
  }
  ASSERT_EQ(cases.size(), 1000u) << file.string() << ": every file of the data set has 1000 cases";
  int failures = 0;
  for (const StepCase& c : cases) {
    std::string d = run_case(c, recompiled);
    if (d.empty()) continue;
    if (++failures <= 5) ADD_FAILURE() << c.name << " (opcode " << hex(c.opcode) << " at " << hex(c.opcode_addr) << "): " << d;
  }
  EXPECT_EQ(failures, 0) << "of " << cases.size() << " cases";
}

TEST_P(SingleStep, AllCasesMatch) { check_all_cases(GetParam(), false); }
TEST_P(SingleStep, AllCasesMatchRecompiled) { check_all_cases(GetParam(), true); }

// One file per instruction; SHL.json.bin holds the SH (store halfword) cases.
const std::vector<std::string> kInstructions = {
    "ADD",  "ADDI", "ADDIU", "ADDU", "AND",  "ANDI", "BCondZ", "BEQ",  "BGTZ", "BLEZ",  "BNE",  "BREAK", "DIV",
    "DIVU", "J",    "JAL",   "JALR", "JR",   "LB",   "LBU",    "LH",   "LHU",  "LUI",   "LW",   "LWL",   "LWR",
    "MFHI", "MFLO", "MTHI",  "MTLO", "MULT", "MULTU", "NOR",   "OR",   "ORI",  "SB",    "SHL",   "SLL",   "SLLV",
    "SLT",  "SLTI", "SLTIU", "SLTU", "SRA",  "SRAV", "SRL",    "SRLV", "SUB",  "SUBU",  "SW",   "SWL",   "SWR",
    "SYSCALL", "XOR", "XORI"};

INSTANTIATE_TEST_SUITE_P(R3000, SingleStep, ::testing::ValuesIn(kInstructions),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace psx
