// `psxrl compat PROGRAMS...`: runs each PS-X EXE or disc image (or every one found in a folder)
// headless under the HLE kernel and, with --bios, under that BIOS too, and writes a report of
// what booted, what stopped each program, and the final pictures (compat_report.h).
#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "cli/cli.h"
#include "cli/compat_report.h"
#include "cli/compat_run.h"
#include "cli/options.h"

namespace psxrl::cli {

namespace {

namespace fs = std::filesystem;

const char* kCompatFooter =
    "PROGRAMS are PS-X EXEs (any name; recognised by the 'PS-X EXE' magic), disc images (.cue,\n"
    ".iso, .bin) or folders, searched recursively (a folder's .bin files are skipped when it has a\n"
    ".cue, which names them). Booted means the program was loaded and started; a disc booted by a\n"
    "BIOS is read by the BIOS itself, so there it shows 'by the BIOS'.\n"
    "\n"
    "exit codes:\n"
    "  0  every program booted and ran to the frame limit or its own exit under every kernel\n"
    "  1  usage error\n"
    "  2  a PROGRAMS path is missing, neither an EXE nor a disc, or a folder with neither (the\n"
    "     others still run); a bad BIOS image; --out unusable (the report is not written)\n"
    "  3  a program did not boot, or stopped on an error (an unsupported BIOS call, an unhandled\n"
    "     exception, a bus error) under some kernel\n";

const std::map<std::string, std::string> kCompatNeeds = {
    {"--frames", "a positive whole number"}, {"--bios", "a file"}, {"--out", "a folder"}, {"--cpu", "a core"},
    {"--jobs", "a whole number from 1 to 256"}};

bool has_exe_magic(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  char magic[8] = {};
  return f.read(magic, sizeof magic) && std::string(magic, sizeof magic) == "PS-X EXE";
}

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

bool is_disc_extension(const std::string& ext) { return ext == ".cue" || ext == ".iso" || ext == ".bin"; }

// The programs in `dir` and below, in path order. A folder's .bin files are its .cue's tracks
// when it has one, not programs of their own.
std::vector<CompatProgram> find_programs(const fs::path& dir, const std::string& shown) {
  std::vector<fs::path> files;
  std::set<fs::path> folders_with_cue;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    files.push_back(it->path());
    if (lower_extension(it->path()) == ".cue") folders_with_cue.insert(it->path().parent_path());
  }
  std::sort(files.begin(), files.end());
  std::vector<CompatProgram> found;
  for (const fs::path& file : files) {
    const std::string ext = lower_extension(file);
    const std::string name = (fs::path(shown) / fs::relative(file, dir, ec)).generic_string();
    if (has_exe_magic(file)) found.push_back({file.string(), name, CompatProgram::Kind::Exe});
    else if (is_disc_extension(ext) && !(ext == ".bin" && folders_with_cue.count(file.parent_path())))
      found.push_back({file.string(), name, CompatProgram::Kind::Disc});
  }
  return found;
}

// A folder's own name ("games" for "../games/" or "/home/me/games"), which its programs' names
// start with in the report.
std::string folder_name(const fs::path& dir) {
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();
  return p.filename().string();
}

// The programs each argument names; prints why an argument names none and counts it in `bad`.
std::vector<CompatProgram> collect(const std::vector<std::string>& args, int& bad) {
  std::vector<CompatProgram> programs;
  for (const std::string& arg : args) {
    std::error_code ec;
    const fs::path path(arg);
    std::string problem;
    if (!fs::exists(path, ec)) {
      problem = "no such file or folder";
    } else if (fs::is_directory(path, ec)) {
      std::vector<CompatProgram> found = find_programs(path, folder_name(path));
      if (found.empty()) problem = "no PS-X EXE or disc image (.cue, .iso, .bin) in this folder or below";
      programs.insert(programs.end(), found.begin(), found.end());
    } else if (has_exe_magic(path)) {
      programs.push_back({arg, arg, CompatProgram::Kind::Exe});
    } else if (is_disc_extension(lower_extension(path))) {
      programs.push_back({arg, arg, CompatProgram::Kind::Disc});
    } else {
      problem = "neither a PS-X EXE (no 'PS-X EXE' magic at offset 0) nor a disc image (.cue, .iso, .bin)";
    }
    if (!problem.empty()) {
      std::fprintf(stderr, "psxrl compat: %s: %s\n", arg.c_str(), problem.c_str());
      ++bad;
    }
  }
  return programs;
}

// Unique screenshot names: a second program with the same slug gets "-2", and so on.
void assign_slugs(std::vector<CompatEntry>& entries) {
  std::set<std::string> used;
  for (CompatEntry& e : entries) {
    const std::string base = compat_slug(e.program.name);
    std::string slug = base;
    for (int n = 2; used.count(slug); ++n) slug = base + "-" + std::to_string(n);
    used.insert(slug);
    e.slug = slug;
  }
}

std::string run_line(const CompatRun& r) {
  if (r.booted == CompatRun::Booted::No) return "did not boot: " + r.stop;
  return std::to_string(r.frames) + " frames" + (r.stop.empty() ? "" : ", " + r.stop);
}

struct CompatArgs {
  std::vector<std::string> programs;
  std::string frames_text = "600", bios, out = "compat-report", cpu = "recompiler", jobs_text = "1";
  bool quiet = false;

  void add_to(CLI::App& app) {
    app.add_option("PROGRAMS", programs, "PS-X EXEs, disc images (.cue, .iso, .bin) or folders of them")
        ->type_name("PATH")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--frames", frames_text, "run each program for N frames (default 600, 10 s of NTSC video)")
        ->type_name("N");
    app.add_option("--bios", bios, "also run each program under this BIOS image (512 KiB) and compare")
        ->type_name("FILE");
    app.add_option("--out", out, "report folder (default compat-report): report.md, index.html,\n"
                                 "screenshots/; replaces an earlier report there, nothing else")
        ->type_name("DIR");
    app.add_option("--cpu", cpu, "CPU core: recompiler (default, faster) or interpreter (the reference);\n"
                   "the same results")
        ->type_name("CORE");
    app.add_option("--jobs", jobs_text, "run N programs at once, each on a console of its own (default 1);\n"
                                        "the report is the same")
        ->type_name("N");
    app.add_flag("--quiet", quiet, "print no progress or table, only errors");
  }
};

// How run_all runs the programs.
struct RunPlan {
  const CompatSettings& hle;
  const CompatSettings* bios;  // null: HLE only
  const CompatReportFolder& folder;
  bool quiet;
  unsigned jobs;
};

void run_entry(CompatEntry& e, const RunPlan& plan) {
  e.hle = run_compat(e.program, plan.hle, plan.folder.screenshot_path(e.slug, "hle"));
  if (plan.bios) e.bios = run_compat(e.program, *plan.bios, plan.folder.screenshot_path(e.slug, "bios"));
}

void print_entry(size_t done, size_t total, const CompatEntry& e) {
  std::fprintf(stderr, "psxrl compat: [%zu/%zu] %s: HLE %s", done, total, e.program.name.c_str(),
               run_line(e.hle).c_str());
  if (e.bios) std::fprintf(stderr, "; BIOS %s; %s picture", run_line(*e.bios).c_str(), e.agree() ? "same" : "different");
  std::fputc('\n', stderr);
}

// Runs every program under every kernel into the report folder, plan.jobs programs at a time
// (each run on a console of its own, so the results do not depend on it), printing each as it
// ends. Returns whether any failed; rethrows the first error writing a screenshot.
bool run_all(std::vector<CompatEntry>& entries, const RunPlan& plan) {
  std::atomic<size_t> next{0};
  std::mutex mutex;  // guards done, error and the progress lines
  size_t done = 0;
  std::exception_ptr error;
  auto work = [&] {
    for (size_t i; (i = next++) < entries.size();) {
      try {
        run_entry(entries[i], plan);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        next = entries.size();
        return;
      }
      std::lock_guard<std::mutex> lock(mutex);
      ++done;
      if (!plan.quiet) print_entry(done, entries.size(), entries[i]);
    }
  };
  std::vector<std::thread> threads;
  for (size_t t = 1; t < std::min<size_t>(plan.jobs, entries.size()); ++t) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  bool failed = false;
  for (const CompatEntry& e : entries) failed = failed || e.hle.failed || (e.bios && e.bios->failed);
  return failed;
}

}  // namespace

int compat_command(const std::vector<std::string>& args) {
  CLI::App app{"Runs PlayStation programs headless under the HLE kernel (and a BIOS, to compare) and\n"
               "reports which boot, what stops them, and their pictures.",
               "psxrl compat"};
  setup_app(app, kCompatFooter);
  CompatArgs a;
  a.add_to(app);
  if (auto code = parse_args(app, args, kCompatNeeds)) return *code;
  CompatSettings hle;
  if (a.frames_text.empty() || a.frames_text.find_first_not_of("0123456789") != std::string::npos ||
      a.frames_text.size() > 9 || std::stoull(a.frames_text) == 0)
    return usage_error(app, "--frames needs a positive whole number (at most 999999999)");
  hle.frames = std::stoull(a.frames_text);
  if (a.cpu != "interpreter" && a.cpu != "recompiler")
    return usage_error(app, "--cpu must be interpreter or recompiler, not '" + a.cpu + "'");
  hle.recompiler = a.cpu == "recompiler";
  if (a.programs.empty()) return usage_error(app, "give at least one program, disc image or folder");
  if (a.jobs_text.empty() || a.jobs_text.find_first_not_of("0123456789") != std::string::npos ||
      a.jobs_text.size() > 3 || std::stoul(a.jobs_text) < 1 || std::stoul(a.jobs_text) > 256)
    return usage_error(app, "--jobs needs a whole number from 1 to 256");
  const unsigned jobs = static_cast<unsigned>(std::stoul(a.jobs_text));

  CompatSettings bios = hle;
  try {
    if (!a.bios.empty()) {
      bios.bios = psx::read_file(a.bios);
      bios.bios_name = a.bios;
      psx::Console().load_bios_image(bios.bios, a.bios);  // checks the size before any run
    }
  } catch (const psx::InputError& e) {
    std::fprintf(stderr, "psxrl compat: %s\n", e.what());
    return kBadInput;
  }
  int bad = 0;
  std::vector<CompatEntry> entries;
  for (CompatProgram& p : collect(a.programs, bad)) entries.push_back({std::move(p), "", {}, std::nullopt});
  assign_slugs(entries);
  bool failed = false;
  try {
    CompatReportFolder folder(a.out);
    failed = run_all(entries, {hle, a.bios.empty() ? nullptr : &bios, folder, a.quiet, jobs});
    folder.commit({hle.frames, a.bios, a.cpu}, entries);
  } catch (const psx::InputError& e) {
    std::fprintf(stderr, "psxrl compat: %s\n", e.what());
    return kBadInput;
  }
  if (!a.quiet) {
    std::fputs(compat_markdown_table(entries, !a.bios.empty()).c_str(), stdout);
    size_t shots = 0;
    for (const CompatEntry& e : entries) shots += e.hle.has_picture + (e.bios && e.bios->has_picture);
    std::fprintf(stderr, "psxrl compat: wrote %s/report.md, %s/index.html and %zu screenshot%s\n", a.out.c_str(),
                 a.out.c_str(), shots, shots == 1 ? "" : "s");
  }
  if (bad) return kBadInput;
  return failed ? kProgramFailed : kSuccess;
}

}  // namespace psxrl::cli
