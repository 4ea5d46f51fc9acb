// GTE register file. The commands arrive with issue #3 (src/core/gte/ is its helper's).
#include "core/gte/gte.h"

namespace psx {

u32 Gte::read_data(u32 r) { return data_[r & 31]; }
void Gte::write_data(u32 r, u32 v) { data_[r & 31] = v; }
u32 Gte::read_control(u32 r) { return control_[r & 31]; }
void Gte::write_control(u32 r, u32 v) { control_[r & 31] = v; }
u32 Gte::execute(u32) { return 1; }

void Gte::do_state(StateIO& s) {
  s.section("GTE ", 1);
  s.pod(data_);
  s.pod(control_);
}

}  // namespace psx
