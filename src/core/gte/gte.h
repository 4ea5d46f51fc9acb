// GTE (Geometry Transformation Engine, COP2): the fixed-point vector unit 3D games use for
// transforms, perspective and lighting (psx-spx "Geometry Transformation Engine").
// Registers 0-31 are the data registers (MFC2/MTC2/LWC2/SWC2), 32-63 the control registers
// (CFC2/CTC2 register r-32).
#pragma once
#include <array>

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

  void do_state(StateIO& s);

 private:
  std::array<u32, 32> data_{};
  std::array<u32, 32> control_{};
};

}  // namespace psx
