// Instantiates the CPU for the console's bus.
#include "core/bus.h"
#include "core/cpu/cpu_impl.h"

namespace psx {
template class CpuT<Bus>;
}
