// psxrl.Console: the seed's PSXPY surface (§3.1, Appendix B) over psx::Console, made synchronous.
// What PSXPY did over pipes is a function call here: pause/resume are simply "not inside a run
// call", a screenshot is a view of the frame buffer, memory listeners are watches whose events are
// taken after a run call. Every call that runs the emulator releases the GIL, so Python threads
// run different consoles in parallel (one console must still be used by one thread at a time).
#include <string>

#include <pybind11/stl.h>

#include "core/console.h"
#include "core/sio/pad_names.h"
#include "python/bindings.h"

namespace py = pybind11;

namespace psxrl::python {
namespace {

// The console plus what the module collects for Python: text the program prints, gathered while
// the GIL is released instead of calling back into Python from inside a run call.
struct PyConsole {
  psx::Console console;
  std::string tty;
  PyConsole(const std::string& renderer, psx::u32 scale) {
    console.on_tty = [this](char c) { tty.push_back(c); };
    if (renderer != "software" && renderer != "gl")
      throw py::value_error("renderer: 'software' or 'gl', not '" + renderer + "'");
    if (scale < 1 || scale > psx::Console::kMaxRenderScale)
      throw py::value_error("scale: 1 to " + std::to_string(psx::Console::kMaxRenderScale) + ", not " + std::to_string(scale));
    if (renderer == "software") {
      if (scale != 1) throw py::value_error("scale: the software renderer draws at 1; use renderer='gl'");
      return;
    }
    std::string error;
    if (!console.use_gl_renderer(scale, error))
      throw std::runtime_error("renderer 'gl': OpenGL is not available: " + error);
  }
};

// Buttons from Python: a bit mask (psxrl.BUTTONS values), a name ("cross"), names joined by "+"
// ("cross+up") or an iterable of any of these.
psx::u16 button_mask(py::handle b) {
  if (py::isinstance<py::bool_>(b)) throw py::type_error("buttons: expected a name, a bit mask or a list, not bool");
  if (py::isinstance<py::int_>(b)) {
    long long v = b.cast<long long>();
    if (v < 0 || v > 0xFFFF) throw py::value_error("buttons: a bit mask is 0..0xFFFF, got " + std::to_string(v));
    return static_cast<psx::u16>(v);
  }
  if (py::isinstance<py::str>(b)) {
    std::string s = b.cast<std::string>();
    psx::u16 mask = 0;
    size_t start = 0;
    while (start <= s.size()) {
      size_t end = s.find('+', start);
      if (end == std::string::npos) end = s.size();
      std::string name = s.substr(start, end - start);
      auto bit = psx::pad_button_from_name(name);
      if (!bit) throw py::value_error("unknown button '" + name + "' (expected " + psx::kPadButtonNameList + ")");
      mask |= *bit;
      start = end + 1;
    }
    return mask;
  }
  if (py::isinstance<py::iterable>(b)) {
    psx::u16 mask = 0;
    for (py::handle item : b) mask |= button_mask(item);
    return mask;
  }
  throw py::type_error("buttons: expected a name, a bit mask or a list of them");
}

psx::Console::PadType pad_type(const std::string& name) {
  if (name == "digital") return psx::Console::PadType::Digital;
  if (name == "dualshock") return psx::Console::PadType::DualShock;
  if (name == "none") return psx::Console::PadType::None;
  throw py::value_error("unknown pad type '" + name + "' (expected digital, dualshock or none)");
}

std::vector<psx::u8> bytes_of(const py::buffer& data) {
  py::buffer_info info = data.request();
  if (info.ndim > 1 || (info.ndim == 1 && info.strides[0] != info.itemsize))
    throw py::value_error("expected bytes or a contiguous one-dimensional buffer");
  const auto* p = static_cast<const psx::u8*>(info.ptr);
  return {p, p + info.size * info.itemsize};
}

const char* capture_state_name(psx::spu::AudioCapture::State s) {
  switch (s) {
    case psx::spu::AudioCapture::State::Idle: return "idle";
    case psx::spu::AudioCapture::State::WaitingForSound: return "waiting";
    case psx::spu::AudioCapture::State::Recording: return "recording";
    case psx::spu::AudioCapture::State::Finished: return "finished";
  }
  return "idle";
}

}  // namespace

py::array samples_array(std::vector<psx::StereoSample>&& samples) {
  static_assert(sizeof(psx::StereoSample) == 4, "StereoSample is two int16 values");
  auto* owned = new std::vector<psx::StereoSample>(std::move(samples));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<psx::StereoSample>*>(p); });
  const std::int16_t* data = owned->empty() ? nullptr : reinterpret_cast<const std::int16_t*>(owned->data());
  if (!data) return array_of<std::int16_t>({0, 2}, data);
  return array_of<std::int16_t>({static_cast<py::ssize_t>(owned->size()), 2}, data, owner);
}

void bind_console(py::module_& m) {
  py::dict buttons;
  for (const auto& [name, bit] : psx::kPadButtonNames) buttons[py::str(std::string(name))] = bit;
  m.attr("BUTTONS") = buttons;

  py::class_<psx::WatchEvent>(m, "WatchEvent", "One guest write into a watched range (taken after a run call).")
      .def_readonly("key", &psx::WatchEvent::key)
      .def_readonly("address", &psx::WatchEvent::address, "physical address written")
      .def_readonly("width", &psx::WatchEvent::width, "bytes written: 1, 2 or 4")
      .def_readonly("old_value", &psx::WatchEvent::old_value)
      .def_readonly("new_value", &psx::WatchEvent::new_value)
      .def_readonly("frame", &psx::WatchEvent::frame)
      .def_readonly("cycle", &psx::WatchEvent::cycle)
      .def("__repr__", [](const psx::WatchEvent& e) {
        return "WatchEvent(key='" + e.key + "', address=" + std::to_string(e.address) + ", width=" +
               std::to_string(e.width) + ", old_value=" + std::to_string(e.old_value) + ", new_value=" +
               std::to_string(e.new_value) + ", frame=" + std::to_string(e.frame) + ")";
      });

  using R = py::gil_scoped_release;
  py::class_<PyConsole>(m, "Console", "One emulated PlayStation (docs/python.md).")
      .def(py::init<const std::string&, psx::u32>(), py::arg("renderer") = "software", py::arg("scale") = 1,
           "renderer='gl' draws with OpenGL on OSMesa at `scale` (1 to 8) times the resolution: get_screen() and "
           "screenshots are that much larger; vram() and states stay native (docs/renderer.md).")
      // Booting (these run the BIOS or read files: the GIL is released).
      .def("load_bios", [](PyConsole& c, const std::string& path) { c.console.load_bios(path); },
           py::arg("path"), py::call_guard<R>())
      .def_property_readonly("has_bios", [](PyConsole& c) { return c.console.has_bios(); })
      .def("boot_exe", [](PyConsole& c, const std::string& path) { c.console.boot_exe(path); }, py::arg("path"),
           py::call_guard<R>())
      .def("boot_bios", [](PyConsole& c) { c.console.boot_bios(); }, py::call_guard<R>())
      .def("insert_disc", [](PyConsole& c, const std::string& path) { c.console.insert_disc(path); },
           py::arg("path"), py::call_guard<R>())
      .def("boot_disc", [](PyConsole& c) { c.console.boot_disc(); }, py::call_guard<R>())
      // Running.
      .def("run_frame", [](PyConsole& c) { c.console.run_frame(); }, py::call_guard<R>())
      .def("run_frames", [](PyConsole& c, psx::u64 n) { c.console.run_frames(n); }, py::arg("n"),
           py::call_guard<R>())
      .def("run_cycles", [](PyConsole& c, psx::u64 n) { c.console.run_cycles(n); }, py::arg("n"),
           py::call_guard<R>())
      .def(
          "run_until",
          [](PyConsole& c, const py::function& done, psx::u64 max_frames) {
            // The condition is Python: it takes the GIL back for each check, between frames.
            R release;
            return c.console.run_until(
                [&] {
                  py::gil_scoped_acquire acquire;
                  return PyObject_IsTrue(done().ptr()) == 1;
                },
                max_frames);
          },
          py::arg("done"), py::arg("max_frames"))
      .def(
          "run_until_equal",
          [](PyConsole& c, psx::u32 address, psx::u32 value, psx::u64 max_frames, int width) {
            if (width != 1 && width != 2 && width != 4) throw py::value_error("width must be 1, 2 or 4");
            c.console.read8(address);  // a bad address fails here, before running
            R release;
            return c.console.run_until(
                [&] {
                  psx::u32 v = width == 1 ? c.console.read8(address)
                               : width == 2 ? c.console.read16(address)
                                            : c.console.read32(address);
                  return v == value;
                },
                max_frames);
          },
          py::arg("address"), py::arg("value"), py::arg("max_frames"), py::arg("width") = 4)
      .def_property_readonly("stopped", [](PyConsole& c) { return c.console.stopped(); })
      .def_property_readonly("exit_code", [](PyConsole& c) { return c.console.exit_code(); })
      .def_property_readonly("fatal_error", [](PyConsole& c) { return c.console.fatal_error(); })
      .def_property_readonly("frames", [](PyConsole& c) { return c.console.frames(); })
      .def_property_readonly("cycles", [](PyConsole& c) { return c.console.cycles(); })
      .def_property_readonly("instructions", [](PyConsole& c) { return c.console.instructions(); })
      .def("take_tty", [](PyConsole& c) { return std::exchange(c.tty, {}); })
      // Input.
      .def("set_buttons", [](PyConsole& c, py::handle b, int port) { c.console.set_buttons(port, button_mask(b)); },
           py::arg("buttons"), py::arg("port") = 1)
      .def("press", [](PyConsole& c, py::handle b, int port) { c.console.press(port, button_mask(b)); },
           py::arg("buttons"), py::arg("port") = 1)
      .def("release", [](PyConsole& c, py::handle b, int port) { c.console.release(port, button_mask(b)); },
           py::arg("buttons"), py::arg("port") = 1)
      .def(
          "press_for",
          [](PyConsole& c, py::handle b, psx::u32 frames, int port) { c.console.press_for(port, button_mask(b), frames); },
          py::arg("buttons"), py::arg("frames"), py::arg("port") = 1)
      .def(
          "set_axes",
          [](PyConsole& c, psx::u8 left_x, psx::u8 left_y, psx::u8 right_x, psx::u8 right_y, int port) {
            psx::AnalogAxes a;
            a.left_x = left_x;
            a.left_y = left_y;
            a.right_x = right_x;
            a.right_y = right_y;
            c.console.set_axes(port, a);
          },
          py::arg("left_x") = 0x80, py::arg("left_y") = 0x80, py::arg("right_x") = 0x80, py::arg("right_y") = 0x80,
          py::arg("port") = 1)
      .def(
          "rumble",
          [](PyConsole& c, int port) {
            psx::Rumble r = c.console.rumble(port);
            return py::make_tuple(r.small, r.large);
          },
          py::arg("port") = 1)
      .def("plug_pad", [](PyConsole& c, int port, const std::string& type) { c.console.plug_pad(port, pad_type(type)); },
           py::arg("port"), py::arg("type"))
      .def("insert_memory_card",
           [](PyConsole& c, int port, const std::string& path) { c.console.insert_memory_card(port, path); },
           py::arg("port"), py::arg("path"))
      // Memory.
      .def("read8", [](PyConsole& c, psx::u32 a) { return c.console.read8(a); }, py::arg("address"))
      .def("read16", [](PyConsole& c, psx::u32 a) { return c.console.read16(a); }, py::arg("address"))
      .def("read32", [](PyConsole& c, psx::u32 a) { return c.console.read32(a); }, py::arg("address"))
      .def("write8", [](PyConsole& c, psx::u32 a, psx::u8 v) { c.console.write8(a, v); }, py::arg("address"),
           py::arg("value"))
      .def("write_byte", [](PyConsole& c, psx::u32 a, psx::u8 v) { c.console.write8(a, v); }, py::arg("address"),
           py::arg("value"))
      .def("write16", [](PyConsole& c, psx::u32 a, psx::u16 v) { c.console.write16(a, v); }, py::arg("address"),
           py::arg("value"))
      .def("write32", [](PyConsole& c, psx::u32 a, psx::u32 v) { c.console.write32(a, v); }, py::arg("address"),
           py::arg("value"))
      .def(
          "read_bytes",
          [](PyConsole& c, psx::u32 address, psx::u32 length) {
            std::string out(length, '\0');
            for (psx::u32 i = 0; i < length; ++i) out[i] = static_cast<char>(c.console.read8(address + i));
            return py::bytes(out);
          },
          py::arg("address"), py::arg("length"))
      .def(
          "write_bytes",
          [](PyConsole& c, psx::u32 address, const py::buffer& data) {
            std::vector<psx::u8> bytes = bytes_of(data);
            for (size_t i = 0; i < bytes.size(); ++i) c.console.write8(address + static_cast<psx::u32>(i), bytes[i]);
          },
          py::arg("address"), py::arg("data"))
      .def(
          "ram",
          [](py::object self) {
            std::span<psx::u8> ram = self.cast<PyConsole&>().console.ram();
            return array_of<psx::u8>({static_cast<py::ssize_t>(ram.size())}, ram.data(), self);
          },
          "The 2 MiB of main RAM as a writable uint8 view (no copy); writes are not reported to watches "
          "or to the recompiler, whose compiled blocks go on running the code they were compiled from "
          "(write code with write_bytes). Nor are they seen by snapshots, so once this view is taken every "
          "restore copies RAM back whole instead of only the pages written.")
      .def("dump_ram", [](PyConsole& c, const std::string& path) { c.console.dump_ram(path); }, py::arg("path"),
           py::call_guard<R>())
      // Memory watches (the seed's listeners).
      .def("watch",
           [](PyConsole& c, const std::string& key, psx::u32 address, psx::u32 length, bool fresh_only,
              psx::u32 flow_limit_frames) { c.console.watch(key, address, length, fresh_only, flow_limit_frames); },
           py::arg("key"), py::arg("address"), py::arg("length"), py::arg("fresh_only") = false,
           py::arg("flow_limit_frames") = 0)
      .def("unwatch", [](PyConsole& c, const std::string& key) { c.console.unwatch(key); }, py::arg("key"))
      .def("sleep_watch", [](PyConsole& c, const std::string& key) { c.console.sleep_watch(key); }, py::arg("key"))
      .def("wake_watch", [](PyConsole& c, const std::string& key) { c.console.wake_watch(key); }, py::arg("key"))
      .def("take_watch_events", [](PyConsole& c) { return c.console.take_watch_events(); })
      // Save states.
      .def(
          "save_state",
          [](PyConsole& c, bool compress) {
            std::vector<psx::u8> blob;
            {
              R release;
              blob = c.console.save_state(compress);
            }
            return py::bytes(reinterpret_cast<const char*>(blob.data()), blob.size());
          },
          py::arg("compress") = false)
      .def(
          "load_state",
          [](PyConsole& c, const py::buffer& data) {
            std::vector<psx::u8> blob = bytes_of(data);
            R release;
            c.console.load_state(blob);
          },
          py::arg("state"))
      .def("save_state_file",
           [](PyConsole& c, const std::string& path, bool compress) { c.console.save_state_file(path, compress); },
           py::arg("path"), py::arg("compress") = true, py::call_guard<R>())
      .def("load_state_file", [](PyConsole& c, const std::string& path) { c.console.load_state_file(path); },
           py::arg("path"), py::call_guard<R>())
      // Video: views of buffers the console owns (fixed allocations, alive as long as the console,
      // which each array keeps alive as its base).
      .def(
          "get_screen",
          [](py::object self) {
            psx::Console::Frame f = self.cast<PyConsole&>().console.frame();
            py::ssize_t w = f.width, h = f.height;
            return read_only(array_of<psx::u8>({h, w, 3}, f.rgb, self));
          },
          "The displayed picture as a read-only [height, width, 3] uint8 view of the console's frame buffer (no "
          "copy). Its pixels change at the next run call; call again after each run call (the size may change).")
      .def(
          "vram",
          [](py::object self) {
            const psx::u16* v = self.cast<PyConsole&>().console.vram();
            return read_only(array_of<psx::u16>({psx::Console::kVramHeight, psx::Console::kVramWidth}, v, self));
          },
          "The GPU's 1024x512 16-bit VRAM as a read-only [512, 1024] uint16 view (no copy).")
      .def("save_screenshot", [](PyConsole& c, const std::string& path) { c.console.save_screenshot(path); },
           py::arg("path"), py::call_guard<R>())
      .def("save_vram_png", [](PyConsole& c, const std::string& path) { c.console.save_vram_png(path); },
           py::arg("path"), py::call_guard<R>())
      // Audio.
      .def("take_audio",
           [](PyConsole& c) {
             std::vector<psx::StereoSample> samples;
             c.console.take_audio(samples);
             return samples_array(std::move(samples));
           })
      .def("keep_all_audio", [](PyConsole& c) { c.console.keep_all_audio(); })
      .def(
          "start_audio_capture",
          [](PyConsole& c, psx::s32 threshold, psx::u32 silence_samples, psx::u32 tail_samples) {
            psx::spu::CaptureOptions o;
            o.threshold = threshold;
            o.silence_samples = silence_samples;
            o.tail_samples = tail_samples;
            c.console.spu().start_capture(o);
          },
          py::arg("threshold") = 1, py::arg("silence_samples") = 0, py::arg("tail_samples") = 0)
      .def("stop_audio_capture", [](PyConsole& c) { return samples_array(c.console.spu().stop_capture()); })
      .def_property_readonly("audio_capture_state",
                             [](PyConsole& c) { return capture_state_name(c.console.spu().capture().state()); })
      .def_static(
          "save_wav",
          [](const std::string& path, const py::array_t<std::int16_t, py::array::c_style | py::array::forcecast>& s) {
            if (s.ndim() != 2 || s.shape(1) != 2) throw py::value_error("save_wav: expected an [N, 2] int16 array");
            auto v = s.unchecked<2>();
            std::vector<psx::StereoSample> samples(static_cast<size_t>(s.shape(0)));
            for (py::ssize_t i = 0; i < v.shape(0); ++i) samples[static_cast<size_t>(i)] = {v(i, 0), v(i, 1)};
            psx::Console::save_wav(path, samples);
          },
          py::arg("path"), py::arg("samples"));
}

}  // namespace psxrl::python
