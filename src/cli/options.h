// Argument parsing for every subcommand with CLI11, with psxrl's conventions: `--help` prints to
// standard output and exits 0; an unknown option or a missing value prints "psxrl CMD: ..." to
// standard error and exits 1 (kUsage).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace psxrl::cli {

// A subcommand's parser: options repeated on the command line keep their last value (as psxrl
// always did), and the footer lists the exit codes.
void setup_app(CLI::App& app, const std::string& exit_codes_footer);

// Parses `args`. Returns an exit code when parsing ends the command (help: 0, usage error: 1) or
// nullopt to go on. `needs` says what each option's value must be ("a file"), for the message
// when it is missing: "--exe needs a file".
std::optional<int> parse_args(CLI::App& app, const std::vector<std::string>& args,
                              const std::map<std::string, std::string>& needs = {});

// For options that name a folder: drops trailing slashes, so "session/" and "session" name the same
// folder everywhere the value is used (its name, a sibling "session.partial", paths inside it).
CLI::Validator folder_path();

// Prints "psxrl CMD: message" and a pointer to --help; returns kUsage.
int usage_error(const CLI::App& app, const std::string& message);

}  // namespace psxrl::cli
