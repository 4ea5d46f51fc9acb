// Candidate encodings, queries and ranking (search.h).
#include "memsearch/search.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace psxrl::memsearch {

using psx::u32;
using psx::u64;
using psx::u8;

namespace {

struct EncodingInfo {
  const char* name;
  u32 size;
  bool is_signed, big_endian, bcd;
};

constexpr EncodingInfo kEncodings[kEncodingCount] = {
    {"u32", 4, false, false, false},  {"s32", 4, true, false, false},   {"u16", 2, false, false, false},
    {"s16", 2, true, false, false},   {"u8", 1, false, false, false},   {"s8", 1, true, false, false},
    {"u32be", 4, false, true, false}, {"s32be", 4, true, true, false},  {"u16be", 2, false, true, false},
    {"s16be", 2, true, true, false},  {"bcd32", 4, false, false, true}, {"bcd16", 2, false, false, true},
    {"bcd8", 1, false, false, true}};

const EncodingInfo& info(Encoding e) { return kEncodings[static_cast<int>(e)]; }

int64_t parse_value(const std::string& text, const std::string& query) {
  try {
    size_t used = 0;
    long long v = std::stoll(text, &used, 0);  // decimal, or 0x hexadecimal
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  throw QueryError("'" + query + "': '" + text + "' is not a whole number (decimal or 0x hex)");
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  double n = static_cast<double>(x.size()), sx = 0, sy = 0;
  for (size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i];
  double mx = sx / n, my = sy / n, cov = 0, vx = 0, vy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    cov += (x[i] - mx) * (y[i] - my);
    vx += (x[i] - mx) * (x[i] - mx);
    vy += (y[i] - my) * (y[i] - my);
  }
  return vx > 0 && vy > 0 ? cov / std::sqrt(vx * vy) : 0;  // a constant never tracks anything
}

}  // namespace

const char* encoding_name(Encoding e) { return info(e).name; }
u32 encoding_size(Encoding e) { return info(e).size; }

bool parse_encoding(const std::string& name, Encoding& out) {
  for (int i = 0; i < kEncodingCount; ++i)
    if (name == kEncodings[i].name) {
      out = static_cast<Encoding>(i);
      return true;
    }
  return false;
}

bool decode(const std::vector<u8>& snap, u32 offset, Encoding e, int64_t& value) {
  const EncodingInfo& k = info(e);
  uint64_t raw = 0;
  for (u32 i = 0; i < k.size; ++i) {
    u32 shift = 8 * (k.big_endian ? k.size - 1 - i : i);
    raw |= static_cast<uint64_t>(snap[offset + i]) << shift;
  }
  if (k.bcd) {
    int64_t v = 0;
    for (int nib = static_cast<int>(k.size) * 2 - 1; nib >= 0; --nib) {
      uint64_t d = (raw >> (4 * nib)) & 0xF;
      if (d > 9) return false;
      v = v * 10 + static_cast<int64_t>(d);
    }
    value = v;
    return true;
  }
  if (k.is_signed && (raw >> (8 * k.size - 1)) & 1) {
    value = static_cast<int64_t>(raw) - (int64_t{1} << (8 * k.size));
    return true;
  }
  value = static_cast<int64_t>(raw);
  return true;
}

std::vector<Encoding> Search::all_encodings() {
  std::vector<Encoding> all;
  for (int i = 0; i < kEncodingCount; ++i) all.push_back(static_cast<Encoding>(i));
  return all;
}

Search::Search(const Session& session, std::vector<Encoding> encodings, u32 first, u32 last) : session_(session) {
  if (session.snapshots.empty()) throw QueryError("the session has no snapshots");
  if (first >= last || last > kSnapshotBytes) throw QueryError("the search range is empty or outside the snapshots");
  for (Encoding e : encodings) {
    Pool pool{e, {}, {}};
    u32 size = encoding_size(e);
    // Naturally aligned, and never straddling RAM's end and the scratchpad's start.
    for (u32 off = (first + size - 1) / size * size; off + size <= last; off += size)
      if (off >= kRamBytes || off + size <= kRamBytes) pool.offsets.push_back(off);
    pools_.push_back(std::move(pool));
  }
}

size_t Search::count() const {
  size_t n = 0;
  for (const Pool& p : pools_) n += p.offsets.size();
  return n;
}

template <typename Keep>
void Search::filter(Keep keep) {
  for (Pool& pool : pools_) {
    size_t out = 0;
    for (size_t i = 0; i < pool.offsets.size(); ++i) {
      double score = pool.scores.empty() ? 0 : pool.scores[i];
      if (!keep(pool.encoding, pool.offsets[i], score)) continue;
      pool.offsets[out] = pool.offsets[i];
      if (!pool.scores.empty()) pool.scores[out] = score;
      ++out;
    }
    pool.offsets.resize(out);
    if (!pool.scores.empty()) pool.scores.resize(out);
  }
}

void Search::equals(size_t snap, int64_t value, bool want_equal) {
  const auto& s = session_.snapshots.at(snap);
  filter([&](Encoding e, u32 off, double&) {
    int64_t v;
    return decode(s, off, e, v) && (v == value) == want_equal;
  });
}

void Search::compare(size_t a, size_t b, Change how) {
  const auto &sa = session_.snapshots.at(a), &sb = session_.snapshots.at(b);
  filter([&](Encoding e, u32 off, double&) {
    int64_t va, vb;
    if (!decode(sa, off, e, va) || !decode(sb, off, e, vb)) return false;
    switch (how) {
      case Change::Changed: return va != vb;
      case Change::Unchanged: return va == vb;
      case Change::Increased: return vb > va;
      case Change::Decreased: return vb < va;
    }
    return false;
  });
}

// Walks the marks in frame order (from the first snapshot when it comes earlier): between each
// point and the next, the word must change exactly when the next point carries one of `labels`.
void Search::changes_at(const std::set<std::string>& labels) {
  std::map<u64, bool> points;  // frame -> carries one of the labels
  points[session_.snapshot_frames.front()] = false;
  bool any = false;
  for (const Mark& m : session_.marks) {
    bool hit = labels.count(m.label) > 0;
    points[m.frame] = points[m.frame] || hit;
    any = any || hit;
  }
  if (!any) throw QueryError("changes-at: no mark carries any of the given labels");
  std::vector<std::pair<size_t, bool>> seq;
  for (const auto& [frame, hit] : points) seq.emplace_back(static_cast<size_t>(session_.snapshot_at(frame)), hit);
  filter([&](Encoding e, u32 off, double&) {
    int64_t prev, cur;
    if (!decode(session_.snapshots[seq[0].first], off, e, prev)) return false;
    for (size_t i = 1; i < seq.size(); ++i) {
      if (!decode(session_.snapshots[seq[i].first], off, e, cur)) return false;
      if ((cur != prev) != seq[i].second) return false;
      prev = cur;
    }
    return true;
  });
}

void Search::tracks(const std::vector<std::pair<size_t, double>>& series, double min_correlation) {
  if (series.size() < 3) throw QueryError("tracks needs a value at three or more points");
  std::vector<double> seen;
  for (const auto& [snap, v] : series) seen.push_back(v);
  for (Pool& pool : pools_)
    if (pool.scores.empty()) pool.scores.assign(pool.offsets.size(), 0);
  std::vector<double> word(series.size());
  filter([&](Encoding e, u32 off, double& score) {
    for (size_t i = 0; i < series.size(); ++i) {
      int64_t v;
      if (!decode(session_.snapshots[series[i].first], off, e, v)) return false;
      word[i] = static_cast<double>(v);
    }
    double r = pearson(word, seen);
    if (r < min_correlation) return false;
    score = std::max(score, r);
    return true;
  });
}

void Search::same_within(const std::set<std::string>& labels) {
  std::vector<std::vector<size_t>> groups;
  for (const std::string& label : labels) groups.push_back(label_snapshots(label));
  state_query_ = true;
  filter([&](Encoding e, u32 off, double&) {
    for (const auto& snaps : groups) {
      int64_t first, v;
      if (!decode(session_.snapshots[snaps[0]], off, e, first)) return false;
      for (size_t snap : snaps)
        if (!decode(session_.snapshots[snap], off, e, v) || v != first) return false;
    }
    return true;
  });
}

void Search::distinct_at_most(size_t n, const std::vector<size_t>& snaps) {
  if (n < 1) throw QueryError("distinct-at most N: N must be at least 1");
  std::vector<size_t> at = snaps;
  if (at.empty())
    for (size_t i = 0; i < session_.snapshots.size(); ++i) at.push_back(i);
  state_query_ = true;
  std::vector<int64_t> seen;
  filter([&](Encoding e, u32 off, double&) {
    seen.clear();
    for (size_t snap : at) {
      int64_t v;
      if (!decode(session_.snapshots[snap], off, e, v)) return false;
      if (std::find(seen.begin(), seen.end(), v) != seen.end()) continue;
      if (seen.size() == n) return false;
      seen.push_back(v);
    }
    return true;
  });
}

void Search::differs_between(const std::string& label1, const std::string& label2) {
  std::vector<size_t> a = label_snapshots(label1), b = label_snapshots(label2);
  state_query_ = true;
  filter([&](Encoding e, u32 off, double&) {
    for (size_t i : a)
      for (size_t j : b) {
        int64_t va, vb;
        if (!decode(session_.snapshots[i], off, e, va) || !decode(session_.snapshots[j], off, e, vb) || va == vb)
          return false;
      }
    return true;
  });
}

std::vector<size_t> Search::label_snapshots(const std::string& label) const {
  std::vector<size_t> snaps;
  for (const Mark& m : session_.marks)
    if (m.label == label) snaps.push_back(static_cast<size_t>(session_.snapshot_at(m.frame)));
  if (snaps.empty()) throw QueryError("no mark is labelled '" + label + "'");
  return snaps;
}

double Search::state_likeness(Encoding e, u32 off) const {
  const auto& snaps = session_.snapshots;
  std::vector<int64_t> v(snaps.size());
  for (size_t i = 0; i < snaps.size(); ++i)
    if (!decode(snaps[i], off, e, v[i])) return 0;
  std::map<std::string, std::vector<int64_t>> by_label;
  for (const Mark& m : session_.marks) by_label[m.label].push_back(v[static_cast<size_t>(session_.snapshot_at(m.frame))]);
  double labels = 0, stable = 0;
  for (const auto& [label, values] : by_label) {
    if (values.size() < 2) continue;
    labels += 1;
    stable += std::all_of(values.begin(), values.end(), [&](int64_t x) { return x == values[0]; }) ? 1 : 0;
  }
  size_t held = 0;
  for (size_t i = 1; i < v.size(); ++i) held += v[i] == v[i - 1];
  std::sort(v.begin(), v.end());
  double distinct = static_cast<double>(std::unique(v.begin(), v.end()) - v.begin());
  bool codes = v.front() >= -128 && v.back() <= 255;
  return (labels > 0 ? stable / labels : 0) + (distinct > 1 ? 2 / distinct : 0) +
         (snaps.size() > 1 ? static_cast<double>(held) / static_cast<double>(snaps.size() - 1) : 0) + (codes ? 1 : 0);
}

size_t Search::resolve_point(const std::string& point) const {
  const Session& s = session_;
  if (point == "start") return 0;
  if (point == "end") return s.snapshots.size() - 1;
  if (!point.empty() && point[0] == '@') {
    u64 frame = 0;
    try {
      size_t used = 0;
      frame = std::stoull(point.substr(1), &used);
      if (used + 1 != point.size()) throw std::invalid_argument(point);
    } catch (const std::exception&) {
      throw QueryError("point '" + point + "': expected @FRAME with a frame number");
    }
    long i = s.snapshot_at(frame);
    if (i < 0) throw QueryError("point '" + point + "': no snapshot was taken at frame " + std::to_string(frame));
    return static_cast<size_t>(i);
  }
  std::string label = point;
  long nth = 0;
  if (size_t hash = point.find('#'); hash != std::string::npos) {
    label = point.substr(0, hash);
    try {
      nth = std::stol(point.substr(hash + 1));
    } catch (const std::exception&) {
      nth = 0;
    }
    if (nth < 1) throw QueryError("point '" + point + "': expected LABEL#N with N from 1");
  }
  std::vector<u64> frames;
  for (const Mark& m : s.marks)
    if (m.label == label) frames.push_back(m.frame);
  if (frames.empty()) throw QueryError("point '" + point + "': no mark is labelled '" + label + "'");
  if (nth == 0 && frames.size() > 1)
    throw QueryError("point '" + point + "': '" + label + "' marks " + std::to_string(frames.size()) +
                     " frames; name one as " + label + "#1.." + label + "#" + std::to_string(frames.size()));
  if (static_cast<size_t>(nth) > frames.size())
    throw QueryError("point '" + point + "': '" + label + "' marks only " + std::to_string(frames.size()) + " frames");
  return static_cast<size_t>(s.snapshot_at(frames[nth ? nth - 1 : 0]));
}

void Search::apply(const std::string& query) {
  std::vector<std::string> w = words(query);
  auto need = [&](size_t n, const char* form) {
    if (w.size() != n) throw QueryError("'" + query + "': expected " + form);
  };
  if (w.empty()) throw QueryError("empty query");
  const std::string& op = w[0];
  if (op == "eq" || op == "ne") {
    need(3, "eq|ne POINT VALUE");
    equals(resolve_point(w[1]), parse_value(w[2], query), op == "eq");
  } else if (op == "changed" || op == "unchanged" || op == "increased" || op == "decreased") {
    need(3, "changed|unchanged|increased|decreased POINT POINT");
    Change how = op == "changed" ? Change::Changed : op == "unchanged" ? Change::Unchanged
               : op == "increased" ? Change::Increased : Change::Decreased;
    compare(resolve_point(w[1]), resolve_point(w[2]), how);
  } else if (op == "changes-at") {
    need(2, "changes-at LABEL[,LABEL...]");
    std::vector<std::string> labels = split(w[1], ',');
    changes_at(std::set<std::string>(labels.begin(), labels.end()));
  } else if (op == "same-within") {
    need(2, "same-within LABEL[,LABEL...]");
    std::vector<std::string> labels = split(w[1], ',');
    same_within(std::set<std::string>(labels.begin(), labels.end()));
  } else if (op == "distinct-at") {
    if ((w.size() != 3 && w.size() != 4) || w[1] != "most")
      throw QueryError("'" + query + "': expected distinct-at most N [LABEL|POINT,...]");
    int64_t n = parse_value(w[2], query);
    if (n < 1) throw QueryError("'" + query + "': N must be at least 1");
    std::vector<size_t> snaps;
    if (w.size() == 4)
      for (const std::string& item : split(w[3], ',')) {
        bool label = std::any_of(session_.marks.begin(), session_.marks.end(), [&](const Mark& m) { return m.label == item; });
        if (!label) {
          snaps.push_back(resolve_point(item));
          continue;
        }
        for (size_t snap : label_snapshots(item)) snaps.push_back(snap);
      }
    distinct_at_most(static_cast<size_t>(n), snaps);
  } else if (op == "differs-between") {
    need(3, "differs-between LABEL1 LABEL2");
    differs_between(w[1], w[2]);
  } else if (op == "tracks") {
    need(2, "tracks POINT=VALUE,POINT=VALUE,... (no spaces)");
    std::vector<std::pair<size_t, double>> series;
    for (const std::string& item : split(w[1], ',')) {
      size_t eq = item.find('=');
      if (eq == std::string::npos) throw QueryError("'" + query + "': '" + item + "' is not POINT=VALUE");
      series.emplace_back(resolve_point(item.substr(0, eq)), static_cast<double>(parse_value(item.substr(eq + 1), query)));
    }
    tracks(series);
  } else {
    throw QueryError("unknown query '" + op +
                     "' (eq, ne, changed, unchanged, increased, decreased, changes-at, tracks, same-within, distinct-at, "
                     "differs-between)");
  }
}

// Survivors at the same offset become one candidate (the first encoding in Encoding order, or its
// signed twin where a value is negative); a narrower survivor inside a surviving wider word (the
// u8 at 0x80010019 inside the u32 at 0x80010018) joins that word's candidate.
void Search::group(std::map<u32, Candidate>& by_offset) const {
  for (u32 width : {4u, 2u}) {
    for (auto it = by_offset.begin(); it != by_offset.end();) {
      u32 word = it->first & ~(width - 1);
      auto wide = by_offset.find(word);
      if (word != it->first && wide != by_offset.end() && encoding_size(wide->second.encoding) == width) {
        merge(wide->second, it->second.encoding, it->second.score);
        it = by_offset.erase(it);
      } else {
        ++it;
      }
    }
  }
}

void Search::add(std::map<u32, Candidate>& by_offset, const Pool& pool, size_t i, double score) const {
  u32 off = pool.offsets[i];
  auto [it, fresh] = by_offset.try_emplace(off, Candidate{off, pool.encoding, score, {}});
  if (!fresh) merge(it->second, pool.encoding, score);
}

std::vector<Candidate> Search::ranked(size_t limit) const {
  std::vector<Candidate> out;
  bool scored = std::any_of(pools_.begin(), pools_.end(), [](const Pool& p) { return !p.scores.empty(); });
  if (scored || state_query_) {
    std::map<u32, Candidate> by_offset;
    for (const Pool& pool : pools_)
      for (size_t i = 0; i < pool.offsets.size(); ++i)
        add(by_offset, pool, i, pool.scores.empty() ? 0 : pool.scores[i]);
    group(by_offset);
    for (auto& [off, c] : by_offset) out.push_back(std::move(c));
    // A state word is judged as it is shown: its row's encoding, not a byte inside it.
    if (!scored)
      for (Candidate& c : out) c.score = state_likeness(c.encoding, c.offset);
    std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
    if (out.size() > limit) out.resize(limit);
    return out;
  }
  // Unscored: address order, so the 4-byte words are walked in order (each pool's offsets are
  // ascending) and the walk stops at `limit`, however many candidates survive.
  std::vector<size_t> cursor(pools_.size(), 0);
  while (out.size() < limit) {
    u32 word = UINT32_MAX;
    for (size_t p = 0; p < pools_.size(); ++p)
      if (cursor[p] < pools_[p].offsets.size()) word = std::min(word, pools_[p].offsets[cursor[p]] & ~3u);
    if (word == UINT32_MAX) break;
    std::map<u32, Candidate> in_word;
    for (size_t p = 0; p < pools_.size(); ++p)
      for (; cursor[p] < pools_[p].offsets.size() && (pools_[p].offsets[cursor[p]] & ~3u) == word; ++cursor[p])
        add(in_word, pools_[p], cursor[p], 0);
    group(in_word);
    for (auto& [off, c] : in_word)
      if (out.size() < limit) out.push_back(std::move(c));
  }
  return out;
}

void Search::merge(Candidate& c, Encoding e, double score) const {
  c.also.push_back(e);
  c.score = std::max(c.score, score);
  const EncodingInfo &a = info(c.encoding), &b = info(e);
  bool signed_twin = b.size == a.size && b.is_signed && !a.is_signed && b.big_endian == a.big_endian && !b.bcd && !a.bcd;
  if (!signed_twin) return;
  for (const auto& snap : session_.snapshots) {
    int64_t v;
    if (decode(snap, c.offset, e, v) && v < 0) {
      c.also.back() = c.encoding;
      c.encoding = e;
      return;
    }
  }
}

}  // namespace psxrl::memsearch
