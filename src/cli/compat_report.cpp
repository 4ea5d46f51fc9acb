// `psxrl compat`'s report writers: the Markdown table, the HTML page, and the staging folder that
// is renamed into place once complete (compat_report.h).
#include "cli/compat_report.h"

#include <unistd.h>

#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace psxrl::cli {

namespace fs = std::filesystem;

bool CompatEntry::agree() const {
  return bios && !hle.failed && !bios->failed && hle.has_picture && bios->has_picture &&
         hle.frame_hash == bios->frame_hash;
}

std::optional<int> CompatEntry::shift() const {
  if (agree()) return 0;
  if (!bios || hle.failed || bios->failed || hle.frames != bios->frames) return std::nullopt;
  return compat_shift(hle.tail_hashes, bios->tail_hashes);
}

std::string compat_slug(const std::string& name) {
  std::string slug = name;
  for (char& c : slug) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                      c == '-' || c == '_';
    if (!keep) c = '_';
  }
  return slug;
}

namespace {

const char* kReportFiles[] = {"report.md", "index.html", "screenshots"};

std::string hex64(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
  return buf;
}

const char* booted_text(CompatRun::Booted b) {
  switch (b) {
    case CompatRun::Booted::Yes: return "yes";
    case CompatRun::Booted::No: return "no";
    case CompatRun::Booted::Unknown: return "by the BIOS";
  }
  return "";
}

// A table cell's text: '|' would end the cell and a line break the row.
std::string md_cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out.empty() ? "-" : out;
}

std::string html_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

// The shift column's text: "0", "+d" or "-d" frames, "-" when the pictures are not the same.
std::string shift_text(const CompatEntry& e) {
  const std::optional<int> d = e.shift();
  if (!d) return "-";
  return (*d > 0 ? "+" : "") + std::to_string(*d);
}

std::string md_row(const CompatEntry& e, const char* kernel, const CompatRun& r, bool with_bios) {
  std::string row = "| " + md_cell(e.program.name) + " | " + kernel + " | " + booted_text(r.booted) + " | " +
                    std::to_string(r.frames) + " | " + md_cell(r.stop) + " | " +
                    (r.has_picture ? std::to_string(r.colours) : "-") + " | " +
                    (r.has_picture ? "`" + hex64(r.frame_hash) + "`" : "-") + " |";
  if (with_bios) row += (e.agree() ? " yes | " : " no | ") + shift_text(e) + " |";
  return row + "\n";
}

std::string heading_text(const CompatHeading& h) {
  std::string text = std::to_string(h.frames) + " frames per run, CPU: " + h.cpu + ". Kernels: HLE";
  if (!h.bios.empty()) text += ", and the BIOS " + h.bios;
  return text + ".";
}

// One kernel's cell of the HTML table: the screenshot and what the run came to.
std::string html_run(const CompatEntry& e, const char* kernel, const CompatRun& r) {
  std::string cell = "<td>";
  if (r.has_picture)
    cell += "<img src=\"" + html_text(CompatReportFolder::screenshot_link(e.slug, kernel)) + "\" alt=\"" +
            html_text(e.program.name) + " under " + kernel + "\" width=\"" + std::to_string(r.width) +
            "\" height=\"" + std::to_string(r.height) + "\"><br>";
  cell += std::string("booted: ") + booted_text(r.booted) + ", " + std::to_string(r.frames) + " frames";
  if (r.has_picture) cell += ", " + std::to_string(r.colours) + " colours, hash <code>" + hex64(r.frame_hash) + "</code>";
  if (!r.stop.empty()) cell += std::string("<br><span class=\"") + (r.failed ? "fail" : "note") + "\">" +
                               html_text(r.stop) + "</span>";
  return cell + "</td>";
}

std::string html_page(const CompatHeading& h, const std::vector<CompatEntry>& entries) {
  const bool with_bios = !h.bios.empty();
  std::string page =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>psxrl compat report</title>\n"
      "<style>\nbody{font-family:sans-serif}table{border-collapse:collapse}td,th{border:1px solid #999;"
      "padding:4px;vertical-align:top}img{image-rendering:pixelated;display:block}.fail{color:#b00}"
      ".note{color:#555}\n</style>\n</head>\n<body>\n<h1>psxrl compat report</h1>\n<p>" +
      html_text(heading_text(h)) + "</p>\n<table>\n<tr><th>Program</th><th>HLE kernel</th>";
  if (with_bios) page += "<th>BIOS</th><th>Same picture</th><th>Same pictures shifted by d frames</th>";
  page += "</tr>\n";
  for (const CompatEntry& e : entries) {
    page += "<tr><td>" + html_text(e.program.name) + "</td>" + html_run(e, "hle", e.hle);
    if (with_bios)
      page += html_run(e, "bios", *e.bios) + "<td>" + (e.agree() ? "yes" : "no") + "</td><td>" + shift_text(e) + "</td>";
    page += "</tr>\n";
  }
  return page + "</table>\n</body>\n</html>\n";
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  f.close();
  if (!f) throw psx::InputError::whole(path.string(), "cannot write the file");
}

// Whether `dir` may be replaced: it is empty or holds nothing but an earlier report's files.
bool replaceable(const fs::path& dir) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    bool known = false;
    for (const char* f : kReportFiles) known = known || name == f;
    if (!known) return false;
  }
  return !ec;
}

}  // namespace

std::string compat_markdown_table(const std::vector<CompatEntry>& entries, bool with_bios) {
  std::string table = "| Program | Kernel | Booted | Frames | First stop | Colours | Frame hash |";
  table += with_bios ? " HLE = BIOS | Same pictures shifted by d frames (HLE frame N = BIOS frame N+d) |\n" : "\n";
  table += "|---|---|---|---:|---|---:|---|";
  table += with_bios ? "---|---:|\n" : "\n";
  for (const CompatEntry& e : entries) {
    table += md_row(e, "HLE", e.hle, with_bios);
    if (with_bios) table += md_row(e, "BIOS", *e.bios, with_bios);
  }
  return table;
}

CompatReportFolder::CompatReportFolder(const std::string& out) : out_(out) {
  std::error_code ec;
  const fs::path dir(out);
  if (fs::exists(dir, ec) && (!fs::is_directory(dir, ec) || !replaceable(dir)))
    throw psx::InputError::whole(out, "exists and is not a psxrl compat report folder (report.md, index.html, "
                                      "screenshots/ only); choose another --out");
  staging_ = out + ".partial-" + std::to_string(::getpid());
  fs::remove_all(staging_, ec);
  if (!fs::create_directories(fs::path(staging_) / "screenshots", ec) || ec)
    throw psx::InputError::whole(out, "cannot create the report folder (first as " + staging_ + "): " + ec.message());
}

CompatReportFolder::~CompatReportFolder() {
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
}

std::string CompatReportFolder::screenshot_link(const std::string& slug, const char* kernel) {
  return "screenshots/" + slug + "-" + kernel + ".png";
}

std::string CompatReportFolder::screenshot_path(const std::string& slug, const char* kernel) const {
  return (fs::path(staging_) / screenshot_link(slug, kernel)).string();
}

void CompatReportFolder::commit(const CompatHeading& heading, const std::vector<CompatEntry>& entries) {
  const fs::path staging(staging_);
  write_text(staging / "report.md", "# psxrl compat report\n\n" + heading_text(heading) + "\n\n" +
                                        compat_markdown_table(entries, !heading.bios.empty()) +
                                        "\nScreenshots: screenshots/; HLE and BIOS side by side: index.html.\n");
  write_text(staging / "index.html", html_page(heading, entries));
  std::error_code ec;
  const fs::path out(out_), old(out_ + ".old-" + std::to_string(::getpid()));
  const bool had_old = fs::exists(out, ec);
  if (had_old) {
    fs::rename(out, old, ec);
    if (ec) throw psx::InputError::whole(out_, "cannot replace the earlier report: " + ec.message());
  }
  fs::rename(staging, out, ec);
  if (ec) {
    std::error_code ignored;
    if (had_old) fs::rename(old, out, ignored);
    throw psx::InputError::whole(out_, "cannot move the report into place: " + ec.message());
  }
  committed_ = true;
  if (had_old) fs::remove_all(old, ec);
}

}  // namespace psxrl::cli
