// psxrl._psxrl.Window: the play window of `psxrl play` (src/frontend/sdl_window.h) for Gymnasium's
// render_mode="human". It only displays pictures it is given; SDL errors (no display) become
// RuntimeError with SDL's reason.
#include <stdexcept>

#include "frontend/sdl_window.h"
#include "python/bindings.h"

namespace py = pybind11;

namespace psxrl::python {

namespace {

using frontend::SdlWindow;
using Rgb = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;

void show(SdlWindow& w, const Rgb& rgb, bool read_back) {
  if (rgb.ndim() != 3 || rgb.shape(2) != 3)
    throw std::invalid_argument("show: expected an RGB picture of shape (height, width, 3)");
  int height = static_cast<int>(rgb.shape(0)), width = static_cast<int>(rgb.shape(1));
  w.show(rgb.data(), width, height, read_back);
}

}  // namespace

void bind_window(py::module_& m) {
  m.def("display_problem", &frontend::display_problem,
        "Why no window can be opened here (no DISPLAY or WAYLAND_DISPLAY), or '' when one can.");
  py::class_<SdlWindow>(m, "Window", "The play window: shows RGB pictures at 4:3, an integer multiple of their size.")
      .def(py::init([](const std::string& title, int width, int height, int scale) {
             if (width <= 0 || height <= 0) throw std::invalid_argument("Window: the picture size must be positive");
             return new SdlWindow(title, frontend::window_size(width, height, scale));
           }),
           py::arg("title"), py::arg("width"), py::arg("height"), py::arg("scale") = 0,
           "A window for pictures of width x height (4:3, scale times their height; 0: 2 below 400 lines).")
      .def("show", &show, py::arg("rgb"), py::arg("read_back") = false,
           "Shows an RGB picture (uint8, height x width x 3) stretched over the window; with read_back, "
           "picture() returns what was drawn.")
      .def("poll", [](SdlWindow& w) { return w.poll().quit; },
           "Handles the window's events; True when the user closed it or pressed Escape.")
      .def("picture",
           [](const SdlWindow& w) {
             frontend::WindowSize s = w.picture_size();
             return array_of<std::uint8_t>({s.height, s.width, 3}, w.picture().data());
           },
           "The window's picture read back by the last show(read_back=True), height x width x 3.");
}

}  // namespace psxrl::python
