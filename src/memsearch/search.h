// Searching a session's RAM for a game's variables: the seed's static analysis (words equal to a
// known value) and dynamic analysis (words that change with the score) as queries. Each query
// narrows the candidate set left by the ones before; what survives is ranked and printed.
//
// A candidate is an address and an encoding (8/16/32-bit, signed or unsigned, little or big
// endian, packed BCD); 16- and 32-bit candidates are naturally aligned, as the R3000A loads them.
// Points name snapshots: `start`, `end`, `@FRAME`, a mark's `LABEL` (when it marks one frame) or
// `LABEL#N` (its Nth frame, from 1).
#pragma once
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "memsearch/session.h"

namespace psxrl::memsearch {

enum class Encoding { U32, S32, U16, S16, U8, S8, U32BE, S32BE, U16BE, S16BE, BCD32, BCD16, BCD8 };
constexpr int kEncodingCount = 13;

const char* encoding_name(Encoding e);
// Parses an encoding's name (u8 s8 u16 s16 u32 s32 u16be s16be u32be s32be bcd8 bcd16 bcd32).
bool parse_encoding(const std::string& name, Encoding& out);
psx::u32 encoding_size(Encoding e);
// The value of `e` at `offset` of a snapshot; false where the bytes are not valid BCD.
bool decode(const std::vector<psx::u8>& snapshot, psx::u32 offset, Encoding e, int64_t& value);

// A query that cannot be understood or refers to something the session lacks.
class QueryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Candidate {
  psx::u32 offset = 0;
  Encoding encoding = Encoding::U32;
  double score = 0;                 // tracks correlation, state likeness (ranked()), else 0
  std::vector<Encoding> also;       // other encodings at the same address that also survived
  psx::u32 address() const { return offset_to_address(offset); }
};

class Search {
 public:
  // Candidates are the words of `encodings` at snapshot offsets [first, last) (session.h maps
  // offsets to addresses); by default all of RAM and the scratchpad.
  explicit Search(const Session& session, std::vector<Encoding> encodings = all_encodings(), psx::u32 first = 0,
                  psx::u32 last = kSnapshotBytes);
  static std::vector<Encoding> all_encodings();

  // One query in the text form `psxrl memsearch` takes (docs/memsearch.md):
  //   eq POINT VALUE | ne POINT VALUE
  //   changed A B | unchanged A B | increased A B | decreased A B
  //   changes-at LABEL[,LABEL...]
  //   tracks POINT=VALUE,POINT=VALUE,...   (a value seen on screen at three or more points)
  //   same-within LABEL[,LABEL...]         (one value at all the marks of each label)
  //   distinct-at most N [ITEM,ITEM...]    (at most N values over the session, or at the items:
  //                                         labels (all their marks) and points)
  //   differs-between LABEL1 LABEL2        (no value at a LABEL1 mark is seen at a LABEL2 mark)
  // Throws QueryError naming what is wrong.
  void apply(const std::string& query);

  // The same queries as calls (snapshots by index; Python uses these).
  void equals(size_t snap, int64_t value, bool want_equal = true);
  enum class Change { Changed, Unchanged, Increased, Decreased };
  void compare(size_t a, size_t b, Change how);
  void changes_at(const std::set<std::string>& labels);
  void tracks(const std::vector<std::pair<size_t, double>>& series, double min_correlation = 0.95);
  void same_within(const std::set<std::string>& labels);
  void distinct_at_most(size_t n, const std::vector<size_t>& snaps);  // empty: every snapshot
  void differs_between(const std::string& label1, const std::string& label2);

  size_t resolve_point(const std::string& point) const;
  // The snapshots of every mark carrying `label` (QueryError when none does).
  std::vector<size_t> label_snapshots(const std::string& label) const;
  size_t count() const;
  // Survivors grouped by address and by the wider word they lie in, best first: by score, then
  // address. After a `tracks` query the score is its correlation; after a game-state query
  // (same-within, distinct-at, differs-between) it is state_likeness(); otherwise survivors come
  // in address order.
  std::vector<Candidate> ranked(size_t limit) const;
  // How much a word looks like a game-state code, 0 to 4: the share of labels (with two or more
  // marks) at whose marks it holds one value; 2 / its number of values over the session (0 for
  // a word that never changes: no variable); the
  // share of consecutive snapshots between which it keeps its value (a state holds still between
  // events and comes in runs, where counters, buffers and stack words move); and 1 when every
  // value is a small code (-128 to 255), as state enumerations are and pointers are not.
  double state_likeness(Encoding e, psx::u32 offset) const;
  const Session& session() const { return session_; }

 private:
  template <typename Keep>
  void filter(Keep keep);
  void merge(Candidate& c, Encoding e, double score) const;
  struct Pool;
  void add(std::map<psx::u32, Candidate>& by_offset, const Pool& pool, size_t i, double score) const;
  void group(std::map<psx::u32, Candidate>& by_offset) const;

  const Session& session_;
  struct Pool {
    Encoding encoding;
    std::vector<psx::u32> offsets;
    std::vector<double> scores;  // parallel to offsets once a tracks query ran
  };
  std::vector<Pool> pools_;
  bool state_query_ = false;  // a game-state query ran: rank by state_likeness()
};

}  // namespace psxrl::memsearch
