// psxrl._psxrl: the extension module behind `import psxrl` (docs/python.md). C++ errors become
// Python exceptions carrying the same message: psx::InputError (a bad user file, integration or
// Lua script) -> psxrl.InputError and psx::StateError (a refused save state) -> psxrl.StateError,
// both ValueError subclasses, since the value handed in is what is wrong; pybind11's own
// translations give std::invalid_argument -> ValueError, std::out_of_range -> IndexError and
// std::logic_error (e.g. a step after the episode ended) -> RuntimeError.
#include "core/input_error.h"
#include "core/state.h"
#include "python/bindings.h"

namespace py = pybind11;

PYBIND11_MODULE(_psxrl, m) {
  m.doc() = "psxrl: PlayStation emulator and reinforcement-learning environments (see docs/python.md)";
  py::register_exception<psx::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<psx::StateError>(m, "StateError", PyExc_ValueError);
  psxrl::python::bind_console(m);
  psxrl::python::bind_env(m);
  psxrl::python::bind_memsearch(m);
  psxrl::python::bind_window(m);
  psxrl::python::bind_record(m);
}
