// GTE (Geometry Transformation Engine, COP2): the fixed-point vector unit 3D games use for
// transforms, perspective and lighting (psx-spx "Geometry Transformation Engine (GTE)").
// Registers 0-31 are the data registers (MFC2/MTC2/LWC2/SWC2), 32-63 the control registers
// (CFC2/CTC2 register r-32). The register file is kept decoded (16-bit fields as s16, matrices
// as 3x3 arrays) so the commands run on plain integers; read/write rebuild the packed views.
//
// Files: gte.cpp (register quirks, dispatch, timing, state), gte_arith.h (MAC/IR/FIFO
// saturation and flags), gte_divide.h (the RTPS/RTPT reciprocal), gte_commands.cpp (geometry
// commands), gte_color.cpp (lighting and depth-cueing commands).
#pragma once
#include <array>
#include <optional>

#include "core/state.h"
#include "core/types.h"

namespace psx {

class Gte {
 public:
  u32 read_data(u32 r);
  void write_data(u32 r, u32 v);
  u32 read_control(u32 r);
  void write_control(u32 r, u32 v);
  // Runs a command (the low 25 bits of the COP2 instruction); returns its duration in cycles.
  u32 execute(u32 command);
  // What execute() runs for `command` (FLAG cleared, then the command), without the dispatch:
  // for the recompiler, which knows the command when it compiles it.
  using Command = void (*)(Gte& gte, u32 command);
  static Command command_function(u32 command);

  void do_state(StateIO& s);

  // Register numbers as seen through read/write: data 0-31, control 32-63 (the numbering of
  // the hardware test vectors). Routes to read_data/read_control.
  u32 read_register(u32 r) { return r < 32 ? read_data(r) : read_control(r - 32); }
  void write_register(u32 r, u32 v) {
    if (r < 32) {
      write_data(r, v);
    } else {
      write_control(r - 32, v);
    }
  }

  // A data register that reads (`write` false) or writes as one field of the register file and
  // nothing else: the field's byte offset in the Gte, its width (2 or 4 bytes; a write keeps the
  // value's low bytes) and whether a 2-byte read is sign-extended. Empty for IRGB/ORGB, for
  // writes to SXYP (a push), LZCS (sets LZCR) and LZCR (read-only). For the recompiler, whose
  // native MFC2/MTC2/LWC2/SWC2 then move the field themselves.
  struct Field {
    u32 offset;
    u32 bytes;
    bool sign;
  };
  static std::optional<Field> data_field(u32 r, bool write);

  // Cycles a command takes (psx-spx "GTE Command Summary"); unknown opcodes take 1. NCDT's are
  // the most.
  static u32 command_cycles(u32 command);
  static constexpr u32 kLongestCommandCycles = 44;

  // FLAG bits (psx-spx "GTE Saturation"). Bit 31 is the OR of kFlagErrorMask.
  static constexpr u32 kFlagMac1Pos = 1u << 30, kFlagMac2Pos = 1u << 29, kFlagMac3Pos = 1u << 28;
  static constexpr u32 kFlagMac1Neg = 1u << 27, kFlagMac2Neg = 1u << 26, kFlagMac3Neg = 1u << 25;
  static constexpr u32 kFlagIr1 = 1u << 24, kFlagIr2 = 1u << 23, kFlagIr3 = 1u << 22;
  static constexpr u32 kFlagColorR = 1u << 21, kFlagColorG = 1u << 20, kFlagColorB = 1u << 19;
  static constexpr u32 kFlagSz3Otz = 1u << 18, kFlagDivide = 1u << 17;
  static constexpr u32 kFlagMac0Pos = 1u << 16, kFlagMac0Neg = 1u << 15;
  static constexpr u32 kFlagSx2 = 1u << 14, kFlagSy2 = 1u << 13, kFlagIr0 = 1u << 12;
  static constexpr u32 kFlagErrorMask = 0x7F87E000;
  static constexpr u32 kFlagError = 1u << 31;

 private:
  using Matrix = std::array<std::array<s16, 3>, 3>;  // [row][column], row 0 = "11 12 13"
  using Vec16 = std::array<s16, 3>;
  using Vec32 = std::array<s32, 3>;

  struct Registers {
    // Data registers.
    std::array<Vec16, 3> v{};       // VXY0/VZ0 .. VXY2/VZ2
    u32 rgbc = 0;                   // RGBC: R, G, B, CODE bytes
    u16 otz = 0;                    // OTZ
    std::array<s16, 4> ir{};        // IR0..IR3
    std::array<u32, 3> sxy{};       // SXY0..SXY2 (X low, Y high, both s16)
    std::array<u16, 4> sz{};        // SZ0..SZ3
    std::array<u32, 3> rgb{};       // RGB0..RGB2 colour FIFO
    u32 res1 = 0;                   // RES1 (unused but read/write)
    std::array<s32, 4> mac{};       // MAC0..MAC3
    u32 lzcs = 0, lzcr = 32;        // LZCS and its leading-bit count
    // Control registers.
    Matrix rt{}, llm{}, lcm{};      // rotation, light, light colour matrices
    Vec32 tr{}, bk{}, fc{};         // translation, background colour, far colour
    s32 ofx = 0, ofy = 0;           // screen offset (16.16)
    u16 h = 0;                      // projection plane distance
    s16 dqa = 0;                    // depth-cueing coefficient
    s32 dqb = 0;                    // depth-cueing offset
    s16 zsf3 = 0, zsf4 = 0;         // AVSZ3/AVSZ4 scale factors
    u32 flag = 0;                   // FLAG bits 12-30 (bit 31 is computed on read)
  };

  // Command decoding: sf selects a 12-bit fraction shift, lm clamps IR1-3 at 0 instead of -8000h.
  struct Op {
    u32 shift;  // 0 or 12 (sf bit 19)
    bool lm;    // bit 10
  };

  // gte_arith.h: saturation, overflow flags, FIFOs and the matrix datapath.
  template <int i> s64 check_mac(s64 v);
  template <int i> void set_ir(s32 v, bool lm);
  template <int i> void set_mac_ir(s64 v, Op op);
  s64 check_mac0(s64 v);
  void set_mac0(s64 v);
  void set_ir0(s64 v);
  void push_sz(s64 z);
  void push_sxy(s64 x, s64 y);
  void push_rgb_from_mac();
  template <int i> s64 dot_row(const Matrix& m, const Vec16& v, s32 t);
  void mul_mat_vec(const Matrix& m, const Vec16& v, const Vec32& t, Op op);
  Vec16 ir_vector() const { return {r_.ir[1], r_.ir[2], r_.ir[3]}; }

  // gte_commands.cpp: geometry.
  void rtp(const Vec16& v, Op op, bool last);
  void rtps(Op op);
  void rtpt(Op op);
  void nclip();
  void op_cross(Op op);
  void mvmva(u32 command, Op op);
  template <int i> void fc_bug_row(const Matrix& m, const Vec16& v, Op op);
  void mul_mat_vec_fc_bug(const Matrix& m, const Vec16& v, Op op);
  void sqr(Op op);
  void set_otz(s64 mac0);
  void avsz3();
  void avsz4();
  void gpf(Op op);
  void gpl(Op op);

  // gte_color.cpp: lighting and depth cueing.
  void interpolate_color(s64 mac1, s64 mac2, s64 mac3, Op op);
  void color_ir(Op op);
  void light_color(const Vec16& normal, Op op);
  void color_times_ir(Op op);
  void depth_cue_color_times_ir(Op op);
  void depth_cue(u32 color, Op op);
  void dpcs(Op op);
  void dpct(Op op);
  void intpl(Op op);
  void dcpl(Op op);
  void ncs(Op op);
  void nct(Op op);
  void nccs(Op op);
  void ncct(Op op);
  void ncds(Op op);
  void ncdt(Op op);
  void cc(Op op);
  void cdp(Op op);

  static Op op_of(u32 command);
  template <void (Gte::*F)(Op)>
  static void run_op(Gte& g, u32 command);

  Registers r_;
};

}  // namespace psx
