// `psxrl memsearch`: searches a recorded session's RAM for a game's variables with a chain of
// queries, prints the ranked survivors with their values at the marks, checks that a session
// replays, and writes found variables out as a new integration's manifest.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli.h"
#include "cli/options.h"
#include "core/console.h"
#include "core/input_error.h"
#include "memsearch/recorder.h"
#include "memsearch/search.h"
#include "memsearch/skeleton.h"

namespace psxrl::cli {

namespace {

const char* kMemsearchFooter =
    "queries (each narrows what the ones before left; POINT is start, end, @FRAME, LABEL or LABEL#N):\n"
    "  eq POINT VALUE          the word equals VALUE at POINT (decimal or 0x hex)\n"
    "  ne POINT VALUE          it does not\n"
    "  changed A B             differs between two points (also unchanged, increased, decreased)\n"
    "  changes-at L1[,L2..]    changes exactly at the marks with these labels, nowhere else\n"
    "                          between consecutive marks\n"
    "  tracks P=V,P=V,...      follows values seen on screen (correlation >= 0.95; ranked by it)\n"
    "  same-within L1[,L2..]   holds one value at all the marks of each label\n"
    "  distinct-at most N [ITEM,..]  takes at most N values over the session, or at the items\n"
    "                          (labels: all their marks; points)\n"
    "  differs-between L1 L2   no value at an L1 mark is seen at an L2 mark\n"
    "  (after the last three, survivors are ranked by how much they look like a game-state code)\n"
    "\n"
    "exit codes:\n"
    "  0  success (with --verify: the session replays exactly)\n"
    "  1  usage error or a query that cannot be understood\n"
    "  2  bad session folder, or the replay does not reproduce the session\n";

constexpr size_t kMaxListed = 200000;  // survivors beyond this are counted, not ranked

struct MemsearchArgs {
  std::string session, encodings, integration, range;
  std::vector<std::string> queries, vars;
  size_t top = 20;
  bool verify = false;

  void add_to(CLI::App& app) {
    app.add_option("session", session, "session folder written by psxrl record")
        ->required()
        ->transform(folder_path());
    app.add_option("queries", queries, "queries, each one argument (quote it)");
    app.add_option("--top", top, "candidates to print (default 20)")->type_name("N");
    app.add_option("--encodings", encodings,
                   "comma-separated encodings to search (default all: u32 s32 u16 s16 u8 s8,\n"
                   "their big-endian forms u32be.. s16be, and bcd32 bcd16 bcd8)")
        ->type_name("LIST");
    app.add_option("--range", range, "search only addresses FIRST-LAST (e.g. 0x80010000-0x80020000; LAST excluded)")
        ->type_name("A-B");
    app.add_flag("--verify", verify, "replay the session from its start state and check every snapshot");
    app.add_option("--integration", integration, "write found variables as DIR/game.toml (a new integration, named after DIR)")
        ->type_name("DIR")
        ->transform(folder_path());
    app.add_option("--var", vars, "a variable for --integration: NAME=ADDRESS:ENCODING (repeatable)")
        ->type_name("SPEC")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  }
};

std::vector<memsearch::Encoding> parse_encodings(const std::string& list) {
  if (list.empty()) return memsearch::Search::all_encodings();
  std::vector<memsearch::Encoding> out;
  size_t start = 0;
  while (start <= list.size()) {
    size_t comma = list.find(',', start);
    std::string name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    memsearch::Encoding e;
    if (!memsearch::parse_encoding(name, e)) throw memsearch::QueryError("--encodings: unknown encoding '" + name + "'");
    out.push_back(e);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// --range FIRST-LAST as snapshot offsets (both addresses in RAM, or both in the scratchpad).
std::pair<psx::u32, psx::u32> parse_range(const std::string& text) {
  if (text.empty()) return {0, memsearch::kSnapshotBytes};
  size_t dash = text.find('-');
  psx::u32 first = 0, last = 0;
  try {
    size_t used = 0;
    unsigned long a = std::stoul(text.substr(0, dash), &used, 0), b = 0;
    if (dash == std::string::npos || used != dash) throw std::invalid_argument(text);
    b = std::stoul(text.substr(dash + 1), &used, 0);
    if (used != text.size() - dash - 1 || a > 0xFFFFFFFFul || b == 0 || b > 0x100000000ul) throw std::invalid_argument(text);
    if (!memsearch::address_to_offset(static_cast<psx::u32>(a), first) ||
        !memsearch::address_to_offset(static_cast<psx::u32>(b - 1), last))
      throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw memsearch::QueryError("--range: expected FIRST-LAST addresses in RAM or the scratchpad, e.g. "
                                "0x80010000-0x80020000, found '" + text + "'");
  }
  if (last < first) throw memsearch::QueryError("--range: LAST is below FIRST");
  return {first, last + 1};
}

// Columns: the start, the marks (at most 10) and the end.
std::vector<std::pair<std::string, size_t>> columns(const memsearch::Session& s) {
  std::vector<std::pair<std::string, size_t>> cols{{"start", 0}};
  for (size_t i = 0; i < s.marks.size() && i < 10; ++i)
    cols.emplace_back(s.marks[i].label, static_cast<size_t>(s.snapshot_at(s.marks[i].frame)));
  cols.emplace_back("end", s.snapshots.size() - 1);
  return cols;
}

void print_table(const memsearch::Search& search, size_t top) {
  const memsearch::Session& s = search.session();
  auto cols = columns(s);
  std::printf("| rank | address | type | score |");
  for (const auto& [label, snap] : cols) std::printf(" %s@%llu |", label.c_str(), static_cast<unsigned long long>(s.snapshot_frames[snap]));
  std::printf("\n|---:|---|---|---:|");
  for (size_t i = 0; i < cols.size(); ++i) std::printf("---:|");
  std::printf("\n");
  size_t rank = 0;
  for (const memsearch::Candidate& c : search.ranked(top)) {
    std::printf("| %zu | 0x%08X | %s | %.4f |", ++rank, c.address(), memsearch::encoding_name(c.encoding), c.score);
    for (const auto& [label, snap] : cols) {
      int64_t v;
      if (memsearch::decode(s.snapshots[snap], c.offset, c.encoding, v)) std::printf(" %lld |", static_cast<long long>(v));
      else std::printf(" - |");
    }
    std::printf("\n");
  }
}

int verify(const memsearch::Session& s) {
  psx::Console console;
  memsearch::boot_source(console, s.source);
  if (auto bad = memsearch::replay_session(console, s)) {
    std::fprintf(stderr, "psxrl memsearch: %s: the replay differs from the recorded RAM at frame %llu\n", s.dir.c_str(),
                 static_cast<unsigned long long>(*bad));
    return kBadInput;
  }
  std::printf("replay: %llu frames, all %zu snapshots identical\n", static_cast<unsigned long long>(s.frames),
              s.snapshots.size());
  return kSuccess;
}

}  // namespace

int memsearch_command(const std::vector<std::string>& args) {
  CLI::App app{"Finds a game's variables in a recorded session's RAM (psxrl record makes sessions).", "psxrl memsearch"};
  setup_app(app, kMemsearchFooter);
  MemsearchArgs a;
  a.add_to(app);
  if (auto code = parse_args(app, args, {{"--top", "a number"}, {"--var", "NAME=ADDRESS:ENCODING"}})) return *code;
  if (!a.vars.empty() && a.integration.empty()) return usage_error(app, "--var needs --integration DIR");

  memsearch::Session session;
  try {
    session = memsearch::read_session(a.session);
    if (a.verify)
      if (int rc = verify(session)) return rc;
  } catch (const psx::InputError& e) {
    std::fprintf(stderr, "psxrl memsearch: %s\n", e.what());
    return kBadInput;
  } catch (const psx::StateError& e) {
    std::fprintf(stderr, "psxrl memsearch: %s/start.state: %s\n", a.session.c_str(), e.what());
    return kBadInput;
  }
  try {
    auto [first, last] = parse_range(a.range);
    memsearch::Search search(session, parse_encodings(a.encodings), first, last);
    for (const std::string& q : a.queries) {
      search.apply(q);
      std::printf("%-40s %zu candidates\n", q.c_str(), search.count());
    }
    if (!a.queries.empty() || (a.integration.empty() && !a.verify)) {
      if (search.count() > kMaxListed) std::printf("%zu candidates: too many to rank, add queries\n", search.count());
      else print_table(search, a.top);
    }
    if (!a.integration.empty()) {
      std::vector<memsearch::FoundVariable> vars;
      for (const std::string& v : a.vars) vars.push_back(memsearch::parse_found_variable(v));
      // A game is chosen by its folder's name, and loading refuses a manifest whose name differs
      // from it, so the name is the folder's ("found_game/" names found_game too).
      std::filesystem::path folder = std::filesystem::path(a.integration).lexically_normal();
      if (!folder.has_filename()) folder = folder.parent_path();
      memsearch::write_integration_skeleton(a.integration, folder.filename().string(), session.source, vars);
      std::printf("wrote %s/game.toml with %zu variables\n", a.integration.c_str(), vars.size());
    }
  } catch (const memsearch::QueryError& e) {
    return usage_error(app, e.what());
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "psxrl memsearch: %s\n", e.what());
    return kBadInput;
  }
  return kSuccess;
}

}  // namespace psxrl::cli
