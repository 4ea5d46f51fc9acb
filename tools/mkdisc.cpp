// mkdisc: the project's disc builder. Makes a bootable PlayStation data disc (one MODE2/2352
// track, ISO 9660, Mode 2 Form 1 sectors with EDC/ECC) as NAME.bin + NAME.cue from a boot EXE,
// an optional SYSTEM.CNF and data files. Both outputs are written to temporary files and renamed.
//
//   mkdisc -o OUT.cue [--exe FILE [--exe-name NAME]] [--cnf FILE] [--volume ID] [--region A|E|I]
//          [FILE[=NAME]...]
//
// Without --cnf, a SYSTEM.CNF booting the EXE is generated. Exit codes: 0 ok, 1 usage, 2 bad input.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/disc/iso_builder.h"
#include "core/input_error.h"

namespace {

using psx::disc::DiscError;
using psx::disc::IsoFile;

struct Usage {
  std::string what;
};

std::vector<psx::u8> read_file(const std::string& path) {
  try {
    return psx::read_file(path);
  } catch (const psx::InputError& e) {
    throw DiscError(e.what());
  }
}

void write_atomically(const std::string& path, const std::vector<psx::u8>& data) {
  try {
    psx::write_file_atomically(path, data);
  } catch (const std::runtime_error& e) {
    throw DiscError(e.what());
  }
}

std::string upper_name(const std::string& path) {
  std::string n = std::filesystem::path(path).filename().string();
  for (char& c : n) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return n;
}

std::string license_text(const std::string& region) {
  const std::string head = "          Licensed  by          Sony Computer Entertainment ";
  if (region == "A") return head + "Amer  ica ";
  if (region == "E") return head + "Euro pe   ";
  if (region == "I") return head + "Inc.      ";
  throw Usage{"--region expects A (America), E (Europe) or I (Japan), not '" + region + "'"};
}

int run(int argc, char** argv) {
  std::string out, exe, exe_name, cnf;
  psx::disc::IsoOptions options;
  std::vector<std::string> extra;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Usage{a + " needs a value"};
      return argv[++i];
    };
    if (a == "-o") out = value();
    else if (a == "--exe") exe = value();
    else if (a == "--exe-name") exe_name = value();
    else if (a == "--cnf") cnf = value();
    else if (a == "--volume") options.volume_id = value();
    else if (a == "--region") options.license_text = license_text(value());
    else if (!a.empty() && a[0] == '-') throw Usage{"unknown option " + a};
    else extra.push_back(a);
  }
  if (out.empty() || std::filesystem::path(out).extension() != ".cue") throw Usage{"-o OUT.cue is required"};
  if (exe.empty() && cnf.empty() && extra.empty()) throw Usage{"nothing to put on the disc"};

  std::vector<IsoFile> files;
  if (!exe.empty()) {
    if (exe_name.empty()) exe_name = upper_name(exe);
    files.push_back({exe_name, read_file(exe)});
  }
  if (!cnf.empty()) {
    files.push_back({"SYSTEM.CNF", read_file(cnf)});
  } else if (!exe.empty()) {
    std::string text = "BOOT = cdrom:\\" + exe_name + ";1\r\nTCB = 4\r\nEVENT = 10\r\nSTACK = 801FFFF0\r\n";
    files.push_back({"SYSTEM.CNF", {text.begin(), text.end()}});
  }
  for (const std::string& spec : extra) {
    size_t eq = spec.find('=');
    std::string path = spec.substr(0, eq);
    files.push_back({eq == std::string::npos ? upper_name(path) : spec.substr(eq + 1), read_file(path)});
  }
  std::vector<psx::u8> image = psx::disc::build_iso(std::move(files), options);
  std::filesystem::path bin = std::filesystem::path(out).replace_extension(".bin");
  write_atomically(bin.string(), image);
  std::string cue = psx::disc::single_track_cue(bin.filename().string());
  write_atomically(out, {cue.begin(), cue.end()});
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const Usage& u) {
    std::fprintf(stderr, "mkdisc: %s\nusage: mkdisc -o OUT.cue [--exe FILE [--exe-name NAME]] [--cnf FILE] "
                         "[--volume ID] [--region A|E|I] [FILE[=NAME]...]\n", u.what.c_str());
    return 1;
  } catch (const DiscError& e) {
    std::fprintf(stderr, "mkdisc: %s\n", e.what());
    return 2;
  }
}
