// Checked Python arguments: a wrong type is a TypeError and a value out of range a ValueError, each
// naming the argument ("max_moves: expected an int from 0 to 4294967295, got -1"), instead of
// pybind11's cast errors that name C++ types and no argument.
#pragma once
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

namespace psxrl::python {

inline std::string type_name(pybind11::handle v) { return pybind11::str(v.get_type().attr("__name__")); }

// An int, or anything with __index__ (NumPy's integers); bool is refused, as a likely mistake.
inline long long int_arg(const char* name, pybind11::handle v, long long lo, long long hi) {
  if (pybind11::isinstance<pybind11::bool_>(v) || !PyIndex_Check(v.ptr()))
    throw pybind11::type_error(std::string(name) + ": expected an int, got " + type_name(v));
  auto i = pybind11::reinterpret_steal<pybind11::object>(PyNumber_Index(v.ptr()));
  if (!i) throw pybind11::error_already_set();
  int overflow = 0;
  long long x = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  if (overflow != 0 || x < lo || x > hi)
    throw pybind11::value_error(std::string(name) + ": expected an int from " + std::to_string(lo) + " to " +
                                std::to_string(hi) + ", got " + std::string(pybind11::str(i)));
  return x;
}

// An unsigned 64-bit int (seeds).
inline std::uint64_t u64_arg(const char* name, pybind11::handle v) {
  if (pybind11::isinstance<pybind11::bool_>(v) || !PyIndex_Check(v.ptr()))
    throw pybind11::type_error(std::string(name) + ": expected an int, got " + type_name(v));
  auto i = pybind11::reinterpret_steal<pybind11::object>(PyNumber_Index(v.ptr()));
  if (!i) throw pybind11::error_already_set();
  unsigned long long x = PyLong_AsUnsignedLongLong(i.ptr());
  if (PyErr_Occurred()) {
    PyErr_Clear();
    throw pybind11::value_error(std::string(name) + ": expected an int from 0 to 2**64 - 1, got " +
                                std::string(pybind11::str(i)));
  }
  return x;
}

// A real number (int or float, not bool).
inline double number_arg(const char* name, pybind11::handle v) {
  if (pybind11::isinstance<pybind11::bool_>(v) || !PyNumber_Check(v.ptr()) || pybind11::isinstance<pybind11::str>(v))
    throw pybind11::type_error(std::string(name) + ": expected a number, got " + type_name(v));
  double x = PyFloat_AsDouble(v.ptr());
  if (PyErr_Occurred()) throw pybind11::error_already_set();
  return x;
}

inline std::string string_arg(const char* name, pybind11::handle v) {
  if (!pybind11::isinstance<pybind11::str>(v))
    throw pybind11::type_error(std::string(name) + ": expected a str, got " + type_name(v));
  return v.cast<std::string>();
}

inline bool bool_arg(const char* name, pybind11::handle v) {
  if (!pybind11::isinstance<pybind11::bool_>(v))
    throw pybind11::type_error(std::string(name) + ": expected True or False, got " + type_name(v));
  return v.cast<bool>();
}

}  // namespace psxrl::python
