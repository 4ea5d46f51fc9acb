// `psxrl compat` on the project's own programs (tests/roms/compat.cmake, Tumble, hello): the
// report's rows, the screenshots, the HTML page that shows them, a picture whose colours are
// known by construction, the same frame hashes from two runs, and an unsupported BIOS call
// reported as the program's first stop.
#include <gtest/gtest.h>
#include <png.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kPsxrl = std::string(PSXRL_BUILD_DIR) + "/psxrl";
const fs::path kRoms = fs::path(PSXRL_BUILD_DIR) / "tests" / "roms";

struct Result {
  int code = -1;
  std::string out;
};

Result run(const std::string& args) {
  Result r;
  FILE* p = ::popen((kPsxrl + " compat " + args + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string slurp(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// report.md's table rows by their first two cells ("program|kernel"), each as its cells.
std::vector<std::vector<std::string>> rows(const std::string& report) {
  std::vector<std::vector<std::string>> out;
  std::istringstream lines(report);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| ", 0) != 0 || line.rfind("| Program", 0) == 0) continue;
    std::vector<std::string> cells;
    std::istringstream parts(line.substr(2));
    for (std::string cell; std::getline(parts, cell, '|');) {
      while (!cell.empty() && cell.back() == ' ') cell.pop_back();
      while (!cell.empty() && cell.front() == ' ') cell.erase(cell.begin());
      cells.push_back(cell);
    }
    out.push_back(cells);
  }
  return out;
}

const std::vector<std::string>* find_row(const std::vector<std::vector<std::string>>& table, const std::string& program,
                                         const std::string& kernel) {
  for (const auto& r : table)
    if (r.size() >= 7 && r[0] == program && r[1] == kernel) return &r;
  return nullptr;
}

// A screenshot's file-name stem as docs/compat.md gives it: the program's name in the report with
// every character but letters, digits, '.', '-' and '_' made '_'.
std::string slug(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return name;
}

// The distinct RGB colours of a PNG, and its size.
struct Png {
  unsigned width = 0, height = 0;
  std::set<unsigned> colours;
};

Png read_png(const fs::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  Png out;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return out;
  image.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> px(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, px.data(), 0, nullptr)) return out;
  out.width = image.width;
  out.height = image.height;
  for (size_t i = 0; i + 2 < px.size(); i += 3) out.colours.insert(px[i] << 16 | px[i + 1] << 8 | px[i + 2]);
  return out;
}

class CompatCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("psxrl_compat_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    progs_ = dir_ / "progs";
    fs::create_directories(progs_ / "discs");
    fs::copy_file(fs::path(PSXRL_BUILD_DIR) / "games" / "tumble" / "tumble.exe", progs_ / "tumble.exe");
    for (const char* exe : {"compat_picture.exe", "compat_unsupported.exe", "hello.exe"})
      fs::copy_file(kRoms / exe, progs_ / exe);
    for (const char* disc : {"compat_picture.cue", "compat_picture.bin"})
      fs::copy_file(kRoms / disc, progs_ / "discs" / disc);
    std::ofstream(progs_ / "notes.txt") << "not a program: the folder search skips it\n";
    std::ofstream(progs_ / "broken.exe") << "PS-X EXE but far too short";
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_, progs_;
};

TEST_F(CompatCommand, ReportsEveryProgramOfAFolderWithScreenshotsAndAnHtmlPage) {
  const fs::path out = dir_ / "report";
  const Result r = run(progs_.string() + " --frames 30 --out " + out.string());
  // compat_unsupported stops on its call and broken.exe cannot boot: exit 3 (`psxrl compat --help`).
  EXPECT_EQ(r.code, 3) << r.out;
  const std::string report = slurp(out / "report.md");
  const auto table = rows(report);
  // Six programs, named from the folder's own name (notes.txt is none; discs/compat_picture.bin
  // is the track its .cue names), HLE only: seven cells a row.
  EXPECT_EQ(table.size(), 6u) << report;
  for (const auto& row : table) EXPECT_EQ(row.size(), 7u) << row[0];

  // The picture's two fills make exactly two colours on the display gpu_init sets up: 320x240.
  const auto* picture = find_row(table, "progs/compat_picture.exe", "HLE");
  ASSERT_NE(picture, nullptr) << report;
  EXPECT_EQ((*picture)[2], "yes");
  EXPECT_EQ((*picture)[3], "30");
  EXPECT_EQ((*picture)[4], "-");
  EXPECT_EQ((*picture)[5], "2");
  const Png shot = read_png(out / "screenshots" / "progs_compat_picture.exe-hle.png");
  EXPECT_EQ(shot.width, 320u);
  EXPECT_EQ(shot.height, 240u);
  EXPECT_EQ(shot.colours.size(), 2u);
  // The same program booted from a disc by the HLE fast boot ends on the same picture.
  const auto* disc = find_row(table, "progs/discs/compat_picture.cue", "HLE");
  ASSERT_NE(disc, nullptr) << report;
  EXPECT_EQ((*disc)[2], "yes");
  EXPECT_EQ((*disc)[6], (*picture)[6]);

  const auto* unsupported = find_row(table, "progs/compat_unsupported.exe", "HLE");
  ASSERT_NE(unsupported, nullptr) << report;
  EXPECT_EQ((*unsupported)[2], "yes");
  EXPECT_NE((*unsupported)[4].find("C0h:7Fh"), std::string::npos) << (*unsupported)[4];
  const auto* broken = find_row(table, "progs/broken.exe", "HLE");
  ASSERT_NE(broken, nullptr) << report;
  EXPECT_EQ((*broken)[2], "no");
  EXPECT_NE((*broken)[4].find("file ends inside the 2048-byte PS-X EXE header"), std::string::npos) << (*broken)[4];
  const auto* hello = find_row(table, "progs/hello.exe", "HLE");
  ASSERT_NE(hello, nullptr) << report;
  EXPECT_EQ((*hello)[4], "exited with code 0");  // its two checks passed (tests/roms/hello.c)
  const auto* tumble = find_row(table, "progs/tumble.exe", "HLE");
  ASSERT_NE(tumble, nullptr) << report;
  EXPECT_EQ((*tumble)[3], "30");
  EXPECT_EQ((*tumble)[4], "-");

  // A screenshot per program that got to a picture (broken.exe did not), each shown by the page.
  const std::string html = slurp(out / "index.html");
  for (const char* slug : {"progs_compat_picture.exe", "progs_compat_unsupported.exe", "progs_hello.exe",
                           "progs_tumble.exe", "progs_discs_compat_picture.cue"}) {
    const std::string link = std::string("screenshots/") + slug + "-hle.png";
    EXPECT_TRUE(fs::is_regular_file(out / link)) << link;
    EXPECT_NE(html.find("<img src=\"" + link + "\""), std::string::npos) << link;
  }
  EXPECT_FALSE(fs::exists(out / "screenshots" / "progs_broken.exe-hle.png"));
  size_t files = 0;
  for (const auto& f : fs::directory_iterator(out / "screenshots")) files += f.is_regular_file();
  EXPECT_EQ(files, 5u);
}

// Runs are deterministic: a second report (replacing the first), its programs run two at a time,
// has the same frame hashes, and is the same report.
TEST_F(CompatCommand, TwoRunsGiveTheSameFrameHashes) {
  const fs::path out = dir_ / "report";
  const std::string args = (progs_ / "compat_picture.exe").string() + " " + (progs_ / "tumble.exe").string() + " " +
                           (progs_ / "hello.exe").string() + " --frames 40 --quiet --out " + out.string();
  ASSERT_EQ(run(args).code, 0);
  const std::string first_report = slurp(out / "report.md");
  ASSERT_EQ(run(args + " --jobs 2").code, 0);
  const std::string second_report = slurp(out / "report.md");
  const auto first = rows(first_report), second = rows(second_report);
  ASSERT_EQ(first.size(), 3u);
  ASSERT_EQ(second.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(first[i][6], second[i][6]) << first[i][0];
    EXPECT_EQ(first[i][6].size(), 18u) << first[i][6];  // `16 hex digits`
  }
  EXPECT_NE(first[0][6], first[1][6]);
  EXPECT_EQ(first_report, second_report);
  EXPECT_FALSE(fs::exists(out.string() + ".partial-" + std::to_string(::getpid())));
}

// Under the project's boot ROM (tests/roms/bootrom.S: no Sony code, it side-loads at the shell
// entry) a program that makes no BIOS call draws what it draws under the HLE kernel.
TEST_F(CompatCommand, HleAndBiosRunsOfTheSamePictureAgree) {
  const fs::path out = dir_ / "report";
  const Result r = run((progs_ / "compat_picture.exe").string() + " --frames 30 --bios " +
                       (kRoms / "bootrom.bin").string() + " --out " + out.string());
  EXPECT_EQ(r.code, 0) << r.out;
  const auto table = rows(slurp(out / "report.md"));
  ASSERT_EQ(table.size(), 2u);
  const std::string name = (progs_ / "compat_picture.exe").string();
  const auto* hle = find_row(table, name, "HLE");
  const auto* bios = find_row(table, name, "BIOS");
  ASSERT_NE(hle, nullptr);
  ASSERT_NE(bios, nullptr);
  ASSERT_EQ(bios->size(), 9u);
  EXPECT_EQ((*bios)[2], "yes");
  EXPECT_EQ((*bios)[5], "2");
  EXPECT_EQ((*bios)[6], (*hle)[6]);
  EXPECT_EQ((*bios)[7], "yes");
  EXPECT_EQ((*bios)[8], "0");  // the shift column: the same pictures at the same frames
  const std::string html = slurp(out / "index.html");
  const size_t hle_img = html.find("<img src=\"screenshots/" + slug(name) + "-hle.png\"");
  const size_t bios_img = html.find("<img src=\"screenshots/" + slug(name) + "-bios.png\"");
  EXPECT_NE(hle_img, std::string::npos) << html;
  EXPECT_NE(bios_img, std::string::npos) << html;
  // Side by side: the same table row holds both.
  EXPECT_EQ(html.find("</tr>", hle_img), html.find("</tr>", bios_img));
}

// The boot ROM hands over in the middle of a frame: that frame is the program's first, as the HLE
// kernel's first frame is, so a picture that changes at every VBlank agrees at the end of both.
// (Counted as the BIOS's, the program saw one VBlank more under the ROM: another colour.)
TEST_F(CompatCommand, HleAndBiosRunsEndOnTheSameVblankOfTheProgram) {
  const fs::path out = dir_ / "report";
  const std::string exe = (kRoms / "compat_frames.exe").string();
  const Result r = run(exe + " --frames 30 --quiet --bios " + (kRoms / "bootrom.bin").string() + " --out " +
                       out.string());
  EXPECT_EQ(r.code, 0) << r.out;
  const auto table = rows(slurp(out / "report.md"));
  const auto* hle = find_row(table, exe, "HLE");
  const auto* bios = find_row(table, exe, "BIOS");
  ASSERT_NE(hle, nullptr);
  ASSERT_NE(bios, nullptr);
  EXPECT_EQ((*hle)[3], "30");
  EXPECT_EQ((*bios)[3], "30");
  EXPECT_EQ((*hle)[5], "1");
  EXPECT_EQ((*bios)[6], (*hle)[6]);
  EXPECT_EQ((*bios)[7], "yes");
}

// A BIOS that never reaches the shell entry (the cdboot ROM waits for a disc) never loads the EXE.
TEST_F(CompatCommand, AnExeTheBiosNeverLoadsDidNotBoot) {
  const fs::path out = dir_ / "report";
  const Result r = run((progs_ / "hello.exe").string() + " --frames 30 --quiet --bios " +
                       (kRoms / "cdboot_rom.bin").string() + " --out " + out.string());
  EXPECT_EQ(r.code, 3) << r.out;
  const auto table = rows(slurp(out / "report.md"));
  const auto* bios = find_row(table, (progs_ / "hello.exe").string(), "BIOS");
  ASSERT_NE(bios, nullptr);
  EXPECT_EQ((*bios)[2], "no");
  EXPECT_NE((*bios)[4].find("did not reach its shell entry"), std::string::npos) << (*bios)[4];
  EXPECT_EQ((*bios)[7], "no");
}

}  // namespace
