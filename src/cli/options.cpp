// CLI11 with psxrl's messages and exit codes (see options.h).
#include "cli/options.h"

#include <algorithm>
#include <cstdio>

#include "cli/cli.h"

namespace psxrl::cli {

void setup_app(CLI::App& app, const std::string& exit_codes_footer) {
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.allow_extras();  // so an unknown option is reported by name, as "unknown option '--x'"
  app.footer(exit_codes_footer);
  app.get_formatter()->column_width(34);
}

CLI::Validator folder_path() {
  return CLI::Validator(
      [](std::string& path) {
        while (path.size() > 1 && path.back() == '/') path.pop_back();
        return std::string();
      },
      "");
}

int usage_error(const CLI::App& app, const std::string& message) {
  std::fprintf(stderr, "%s: %s\nsee '%s --help' for the options\n", app.get_name().c_str(), message.c_str(),
               app.get_name().c_str());
  return kUsage;
}

std::optional<int> parse_args(CLI::App& app, const std::vector<std::string>& args,
                              const std::map<std::string, std::string>& needs) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return kSuccess;
  } catch (const CLI::ArgumentMismatch& e) {
    // CLI11 names the option in its message; the longest name found is the one meant
    // ("--screenshot-at", not "--screenshot").
    std::string what = e.what(), best;
    for (const auto& [name, need] : needs)
      if (what.find(name) != std::string::npos && name.size() > best.size()) best = name;
    return usage_error(app, best.empty() ? what : best + " needs " + needs.at(best));
  } catch (const CLI::ParseError& e) {
    return usage_error(app, e.what());
  }
  std::vector<std::string> extra = app.remaining();
  if (!extra.empty()) return usage_error(app, "unknown option '" + extra.front() + "'");
  return std::nullopt;
}

}  // namespace psxrl::cli
