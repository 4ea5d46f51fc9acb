// The pieces of the `psxrl._psxrl` extension module, one function per binding file, and the array
// helpers they share.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

#include "core/audio_fifo.h"

namespace psxrl::python {

void bind_console(pybind11::module_& m);
void bind_env(pybind11::module_& m);
void bind_memsearch(pybind11::module_& m);
void bind_window(pybind11::module_& m);
void bind_record(pybind11::module_& m);

// C-order strides for `shape` with items of `itemsize` bytes. Every array made over C++ memory
// passes them explicitly: pybind11 before 2.12 (Debian 12 ships 2.10) reads a dtype's item size
// at NumPy 1's descriptor offset, which NumPy 2 moved, and would compute zero strides.
inline std::vector<pybind11::ssize_t> c_strides(const std::vector<pybind11::ssize_t>& shape, size_t itemsize) {
  std::vector<pybind11::ssize_t> strides(shape.size(), static_cast<pybind11::ssize_t>(itemsize));
  for (size_t i = shape.size(); i-- > 1;) strides[i - 1] = strides[i] * shape[i];
  return strides;
}

// An array of `shape` over `data`: a view kept alive by `base`, or a copy when there is no base.
template <typename T>
pybind11::array_t<T> array_of(const std::vector<pybind11::ssize_t>& shape, const T* data,
                              pybind11::handle base = pybind11::handle()) {
  return pybind11::array_t<T>(shape, c_strides(shape, sizeof(T)), data, base);
}

// Stereo samples as an [N, 2] int16 array that owns the vector (moved, not copied).
pybind11::array samples_array(std::vector<psx::StereoSample>&& samples);

// Marks an array read-only: views of buffers the emulator owns must not be written through.
inline pybind11::array read_only(pybind11::array a) {
  a.attr("setflags")(pybind11::arg("write") = false);
  return a;
}

}  // namespace psxrl::python
