// `psxrl compat`'s report folder: report.md (a Markdown table, one row per program and kernel),
// screenshots/ (a PNG per program per kernel) and index.html (the table with the HLE and BIOS
// screenshots side by side). The folder is built under a temporary name beside --out and renamed
// into place only when complete, so an error never leaves a half-written report.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "cli/compat_run.h"

namespace psxrl::cli {

// One program's results: under the HLE kernel and, with --bios, under the BIOS.
struct CompatEntry {
  CompatProgram program;
  std::string slug;  // its screenshots' file name stem, unique in the report
  CompatRun hle;
  std::optional<CompatRun> bios;
  // Both runs went without an error and ended on the same picture (the same frame hash); only
  // with a BIOS run. Two runs stopped by errors on the same blank screen do not agree.
  bool agree() const;
  // When they do not agree but both ran all their frames without an error: the shift d at which
  // the HLE run's last frames show the BIOS run's pictures (HLE frame N = BIOS frame N + d,
  // compat_shift()); 0 when they agree; nothing otherwise. A column of its own: "HLE = BIOS"
  // stays the strict comparison.
  std::optional<int> shift() const;
};

// What the report's heading says about the runs.
struct CompatHeading {
  std::uint64_t frames = 0;
  std::string bios;  // the --bios file, or "" for HLE only
  std::string cpu;
};

// The staging folder for a report that replaces `out`, created at once: throws InputError when
// `out` exists and is neither empty nor an earlier report (nothing of the user's is replaced),
// or when the folder cannot be created.
class CompatReportFolder {
 public:
  explicit CompatReportFolder(const std::string& out);
  ~CompatReportFolder();  // removes the staging folder unless commit() succeeded
  CompatReportFolder(const CompatReportFolder&) = delete;
  CompatReportFolder& operator=(const CompatReportFolder&) = delete;

  // The path a screenshot is written to now, and the one the report links to.
  std::string screenshot_path(const std::string& slug, const char* kernel) const;
  static std::string screenshot_link(const std::string& slug, const char* kernel);
  // Writes report.md and index.html and renames the folder to `out` (an earlier report there is
  // replaced). Throws InputError naming the file or folder that failed.
  void commit(const CompatHeading& heading, const std::vector<CompatEntry>& entries);

 private:
  std::string out_, staging_;
  bool committed_ = false;
};

// The Markdown table alone (report.md's body; also printed by the command).
std::string compat_markdown_table(const std::vector<CompatEntry>& entries, bool with_bios);

// A file-name stem from a program's name: letters, digits, '.', '-' and '_' kept, the rest '_'.
std::string compat_slug(const std::string& name);

}  // namespace psxrl::cli
