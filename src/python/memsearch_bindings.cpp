// psxrl.Session and psxrl.Search: recorded play sessions and memory-search queries from Python
// (docs/memsearch.md), returning NumPy arrays. A Search keeps its Session alive.
#include <pybind11/stl.h>

#include "core/console.h"
#include "memsearch/recorder.h"
#include "memsearch/search.h"
#include "memsearch/session.h"
#include "python/bindings.h"

namespace py = pybind11;
namespace ms = psxrl::memsearch;

namespace psxrl::python {

namespace {

ms::Encoding encoding_of(const std::string& name) {
  ms::Encoding e;
  if (!ms::parse_encoding(name, e)) throw std::invalid_argument("unknown encoding '" + name + "'");
  return e;
}

std::vector<ms::Encoding> encodings_of(const std::optional<std::vector<std::string>>& names) {
  if (!names) return ms::Search::all_encodings();
  std::vector<ms::Encoding> out;
  for (const std::string& n : *names) out.push_back(encoding_of(n));
  return out;
}

// The value of one word at every snapshot (int64; where BCD digits are invalid, the minimum).
py::array_t<int64_t> values(const ms::Session& s, psx::u32 address, const std::string& encoding) {
  ms::Encoding e = encoding_of(encoding);
  psx::u32 off = 0;
  if (!ms::address_to_offset(address, off) || off + ms::encoding_size(e) > ms::kSnapshotBytes)
    throw std::invalid_argument("address is not in RAM or the scratchpad");
  std::vector<int64_t> v(s.snapshots.size(), INT64_MIN);
  for (size_t i = 0; i < s.snapshots.size(); ++i) ms::decode(s.snapshots[i], off, e, v[i]);
  return array_of<int64_t>({static_cast<py::ssize_t>(v.size())}, v.data());
}

// Ranked candidates as a dict of arrays: address (uint32), encoding (str list), score (float64).
py::dict ranked(const ms::Search& s, size_t limit) {
  auto top = s.ranked(limit);
  std::vector<uint32_t> addr;
  std::vector<double> score;
  py::list enc;
  for (const ms::Candidate& c : top) {
    addr.push_back(c.address());
    score.push_back(c.score);
    enc.append(ms::encoding_name(c.encoding));
  }
  py::ssize_t n = static_cast<py::ssize_t>(top.size());
  py::dict d;
  d["address"] = array_of<uint32_t>({n}, addr.data());
  d["encoding"] = enc;
  d["score"] = array_of<double>({n}, score.data());
  return d;
}

}  // namespace

void bind_memsearch(py::module_& m) {
  py::register_exception<ms::QueryError>(m, "QueryError", PyExc_ValueError);

  py::class_<ms::Session>(m, "Session", "A play session recorded by `psxrl record` (read-only).")
      .def(py::init(&ms::read_session), py::arg("path"))
      .def_readonly("frames", &ms::Session::frames)
      .def_readonly("snapshot_interval", &ms::Session::snapshot_interval)
      .def_property_readonly("marks",
                             [](const ms::Session& s) {
                               py::list out;
                               for (const ms::Mark& mk : s.marks) out.append(py::make_tuple(mk.frame, mk.label));
                               return out;
                             })
      .def_property_readonly("snapshot_frames",
                             [](const ms::Session& s) { return array_of<psx::u64>({static_cast<py::ssize_t>(s.snapshot_frames.size())}, s.snapshot_frames.data()); })
      .def_property_readonly("inputs",
                             [](const ms::Session& s) {
                               std::vector<psx::u16> v;
                               for (size_t f = 0; f < s.frames; ++f) v.push_back(s.pad1[f]), v.push_back(s.pad2[f]);
                               return array_of<psx::u16>({static_cast<py::ssize_t>(s.frames), 2}, v.data());
                             })
      .def(
          "snapshot",
          [](py::object self, size_t i) {
            const ms::Session& s = self.cast<const ms::Session&>();
            const auto& snap = s.snapshots.at(i);
            return read_only(array_of<psx::u8>({static_cast<py::ssize_t>(snap.size())}, snap.data(), self));
          },
          py::arg("index"), "RAM (2 MiB) then scratchpad (1 KiB) at snapshot `index`: a read-only view.")
      .def("snapshot_at", &ms::Session::snapshot_at, py::arg("frame"))
      .def("values", &values, py::arg("address"), py::arg("encoding") = "u32",
           "One word's value at every snapshot, as int64.")
      .def(
          "replay",
          [](const ms::Session& s) {
            psx::Console console;
            ms::boot_source(console, s.source);
            py::gil_scoped_release release;
            return ms::replay_session(console, s);
          },
          "Replays from the start state; None when every snapshot matches, else the first frame that differs.")
      .def(
          "search",
          [](py::object self, std::optional<std::vector<std::string>> encodings, std::optional<psx::u32> first,
             std::optional<psx::u32> last) {
            psx::u32 a = 0, b = ms::kSnapshotBytes - 1;
            if (first.has_value() != last.has_value()) throw std::invalid_argument("give both first and last, or neither");
            if (first && (!ms::address_to_offset(*first, a) || *last == 0 || !ms::address_to_offset(*last - 1, b) || b < a))
              throw std::invalid_argument("first..last must be addresses in RAM or the scratchpad, first below last");
            return std::make_unique<ms::Search>(self.cast<const ms::Session&>(), encodings_of(encodings), a, b + 1);
          },
          py::arg("encodings") = py::none(), py::arg("first") = py::none(), py::arg("last") = py::none(),
          py::keep_alive<0, 1>(), "Candidates in [first, last) (default: all of RAM and the scratchpad).");

  py::class_<ms::Search>(m, "Search", "Candidate words narrowed by queries (Session.search()).")
      .def("apply", &ms::Search::apply, py::arg("query"), "One query in psxrl memsearch's text form.")
      .def("eq", [](ms::Search& s, const std::string& p, int64_t v) { s.equals(s.resolve_point(p), v); })
      .def("ne", [](ms::Search& s, const std::string& p, int64_t v) { s.equals(s.resolve_point(p), v, false); })
      .def("changed", [](ms::Search& s, const std::string& a, const std::string& b) {
        s.compare(s.resolve_point(a), s.resolve_point(b), ms::Search::Change::Changed);
      })
      .def("unchanged", [](ms::Search& s, const std::string& a, const std::string& b) {
        s.compare(s.resolve_point(a), s.resolve_point(b), ms::Search::Change::Unchanged);
      })
      .def("increased", [](ms::Search& s, const std::string& a, const std::string& b) {
        s.compare(s.resolve_point(a), s.resolve_point(b), ms::Search::Change::Increased);
      })
      .def("decreased", [](ms::Search& s, const std::string& a, const std::string& b) {
        s.compare(s.resolve_point(a), s.resolve_point(b), ms::Search::Change::Decreased);
      })
      .def("changes_at", [](ms::Search& s, const std::set<std::string>& labels) { s.changes_at(labels); })
      .def(
          "tracks",
          [](ms::Search& s, const std::map<std::string, double>& seen, double min_correlation) {
            std::vector<std::pair<size_t, double>> series;
            for (const auto& [point, v] : seen) series.emplace_back(s.resolve_point(point), v);
            s.tracks(series, min_correlation);
          },
          py::arg("seen"), py::arg("min_correlation") = 0.95)
      .def_property_readonly("count", &ms::Search::count)
      .def("ranked", &ranked, py::arg("limit") = 20,
           "Best candidates: {'address': uint32 array, 'encoding': [str], 'score': float64 array}.");
}

}  // namespace psxrl::python
