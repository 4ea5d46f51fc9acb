// Interrupt controller register access.
#include "core/irq.h"

namespace psx {

u32 InterruptController::read(u32 offset) const {
  switch (offset & 0xC) {
    case 0x0: return stat_;
    case 0x4: return mask_;
    default: return 0;
  }
}

void InterruptController::write(u32 offset, u32 value) {
  switch (offset & 0xC) {
    case 0x0: stat_ &= value & kUsedBits; break;  // writing 0 acknowledges, 1 keeps
    case 0x4: mask_ = value & kUsedBits; break;
    default: break;
  }
}

}  // namespace psx
