// psxrl._psxrl.Recorder: every emulated frame an Env plays from now on, picture and sound, to a
// video file (MP4/MKV/MOV through FFmpeg, src/frontend/video_writer.h) or to PNG pictures with
// audio.wav in a folder: the recording of `psxrl play --record`, for Python. The recorder hooks
// the Env's per-frame callback until close(); a video is only renamed into place by close(), so
// an interrupted recording leaves no half-written file.
#include <memory>
#include <stdexcept>
#include <string>

#include "frontend/recorder.h"
#include "python/bindings.h"
#include "rl/env.h"

namespace py = pybind11;

namespace psxrl::python {

namespace {

class EnvRecorder {
 public:
  EnvRecorder(rl::Env& env, const std::string& target, int every) : env_(env) {
    if (env.on_frame) throw std::logic_error("Recorder: this Env is already being recorded");
    recorder_ = std::make_unique<frontend::Recorder>(target, every, frontend::console_frame_rate(env.console()));
    env.on_frame = [this](std::span<const psx::StereoSample> audio) {
      psx::Console::Frame f = env_.console().frame();
      recorder_->frame(f.rgb, static_cast<int>(f.width), static_cast<int>(f.height), audio);
    };
  }
  ~EnvRecorder() { detach(); }  // without close(): the recorder removes its temporary video
  EnvRecorder(const EnvRecorder&) = delete;
  EnvRecorder& operator=(const EnvRecorder&) = delete;

  // Stops recording and completes the files; returns what was written. Closing twice is harmless.
  std::string close() {
    if (!recorder_) return "nothing (the recording was abandoned)";
    if (detach()) recorder_->finish();
    return recorder_->summary();
  }
  // Stops recording without completing: a video's temporary file is removed.
  void abandon() {
    detach();
    recorder_.reset();
  }
  bool recording() const { return attached_; }

 private:
  bool detach() {
    if (!attached_) return false;
    env_.on_frame = nullptr;
    attached_ = false;
    return true;
  }

  rl::Env& env_;
  std::unique_ptr<frontend::Recorder> recorder_;
  bool attached_ = true;
};

}  // namespace

void bind_record(py::module_& m) {
  py::class_<EnvRecorder>(m, "Recorder",
                          "Records every emulated frame an Env plays (picture and sound) until close(): "
                          "a .mp4/.mkv/.mov video, or PNG pictures and audio.wav in a folder.")
      .def(py::init<rl::Env&, const std::string&, int>(), py::arg("env"), py::arg("target"), py::arg("every") = 1,
           py::keep_alive<1, 2>(),
           "Starts recording `env`; `every`: keep 1 picture in N frames (the sound is always whole).")
      .def("close", &EnvRecorder::close, "Completes the files and stops recording; returns what was written.")
      .def_property_readonly("recording", &EnvRecorder::recording)
      .def("__enter__", [](EnvRecorder& r) -> EnvRecorder& { return r; }, py::return_value_policy::reference)
      .def("abandon", &EnvRecorder::abandon, "Stops recording without completing the files (no video is left).")
      .def("__exit__", [](EnvRecorder& r, const py::object& type, const py::object&, const py::object&) {
        // An exception inside the with block abandons the recording: no half-written video.
        if (type.is_none()) r.close();
        else r.abandon();
      });
}

}  // namespace psxrl::python
