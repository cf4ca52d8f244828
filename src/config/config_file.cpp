#include "config/config_file.hpp"

#include "config/flag_table.hpp"
#include "config/numbers.hpp"
#include "config/paths.hpp"
#include "config/same_run.hpp"
#include "core/text.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <concepts>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace gbssn1d {

namespace {

/// A numeric option bound to `target` (int, double or an optional double) and read by the one
/// number reader (config/numbers.hpp), not by CLI11's, which reads leading zeros as octal; a bad
/// value is a ParamError naming the option's first name. --help shows the target's value (an
/// unset optional shows none).
template <class T>
CLI::Option* number_option(CLI::App& app, const std::string& names, T& target,
                           const std::string& help) {
  using Number = std::conditional_t<std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>,
                                    int, double>;
  const std::string flag = names.substr(0, names.find(','));
  CLI::Option* opt = app.add_option_function<std::string>(
      names,
      [&target, flag](const std::string& text) { target = parse_number<Number>(flag, text); },
      help);
  if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>>) {
    if (target)
      opt->default_str(fmt::format("{}", *target));
  } else {
    opt->default_str(fmt::format("{}", target));
  }
  return opt->type_name(std::is_same_v<Number, int> ? "INT" : "FLOAT");
}

} // namespace

void add_options(CLI::App& app, Params& p) {
  for (const auto& spec : param_specs()) {
    const std::string flag = std::string("--") + spec.name;
    std::visit(
        [&](auto member) {
          using T = std::decay_t<decltype(p.*member)>;
          CLI::Option* opt;
          if constexpr (std::is_same_v<T, bool>) {
            opt = app.add_flag(flag, p.*member, spec.help);
          } else if constexpr (std::is_same_v<T, std::string>) {
            opt = app.add_option(flag, p.*member, spec.help)->capture_default_str();
          } else if constexpr (ChoiceValue<T>) {
            auto& target = p.*member;
            opt = app.add_option_function<std::string>(
                         flag, [&target](const std::string& text) { target = T::parse(text); },
                         spec.help)
                      ->type_name("TEXT")
                      ->default_str(target.name());
          } else if constexpr (is_optional_choice<T>) {
            auto& target = p.*member;
            opt =
                app.add_option_function<std::string>(
                       flag,
                       [&target](const std::string& text) { target = T::value_type::parse(text); },
                       spec.help)
                    ->type_name("TEXT");
          } else {
            opt = number_option(app, flag, p.*member, spec.help);
          }
          opt->group(spec.group);
          if (const auto rule = default_rules().find(spec.name); rule != default_rules().end())
            opt->default_str(rule->second);
        },
        spec.member);
  }
}

CLI::Option* add_number_option(CLI::App& app, const std::string& names, int& target,
                               const std::string& help) {
  return number_option(app, names, target, help);
}

CLI::Option* add_number_option(CLI::App& app, const std::string& names, double& target,
                               const std::string& help) {
  return number_option(app, names, target, help);
}

std::string config_text(const Params& p) {
  std::string text;
  for (const auto& spec : param_specs())
    if (const auto value = value_text(p, spec))
      text += fmt::format("{} = {}\n", spec.name, *value);
  return text;
}

namespace {

/// The keys a config file's rule-values line names (same_run.hpp: rule_values_line): the keys
/// the run did not give, but their rules, left to their rules again as the run left them.
std::set<std::string> ruled_keys(const std::string& text, const std::string& path) {
  std::set<std::string> ruled;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with(rule_values_mark))
      continue;
    std::istringstream keys(line.substr(rule_values_mark.size()));
    for (std::string key; std::getline(keys, key, ',');) {
      key.erase(0, key.find_first_not_of(' '));
      key.erase(key.find_last_not_of(" \r") + 1);
      const auto& known = rule_keys();
      if (std::find(known.begin(), known.end(), key) == known.end())
        throw ParamError("--config", path,
                         fmt::format("its line '{}' names '{}', which no rule gives",
                                     printable(std::string(rule_values_mark.substr(2))),
                                     printable(key)));
      ruled.insert(key);
    }
  }
  return ruled;
}

/// The config file at `path` read as `--key=value` arguments into `from_file`, each flag's file
/// recorded in `file_of`.
void read_config_args(const std::string& path, std::vector<std::string>& from_file,
                      std::map<std::string, std::string>& file_of) {
  check_input_file("--config", path);
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  if (!file && !file.eof())
    throw ParamError("--config", path, "cannot be read");
  const std::set<std::string> ruled = ruled_keys(text.str(), path);
  for (const auto& [key, value] : read_config_text(text.str(), path)) {
    if (ruled.count(key) != 0)
      continue;
    const auto spec = std::find_if(param_specs().begin(), param_specs().end(),
                                   [&](const ParamSpec& s) { return key == s.name; });
    if (spec == param_specs().end())
      throw ParamError("--config", path, fmt::format("unknown key '{}'", printable(key)));
    if (std::holds_alternative<bool Params::*>(spec->member) && value != "true" && value != "false")
      throw ParamError(
          "--config", path,
          fmt::format("key '{}' must be true or false, not '{}'", key, printable(value)));
    // Writing into an existing folder is asked for on the command line only: a recorded
    // `force = true` (a config.toml of a run made with --force) must not let a rerun with
    // that file overwrite a finished run.
    if (key == "force")
      continue;
    // "--key=" with an empty value would take the next argument as its value: pass the
    // empty value as a separate argument
    file_of["--" + key] = path;
    if (value.empty()) {
      from_file.push_back("--" + key);
      from_file.push_back("");
    } else {
      from_file.push_back(fmt::format("--{}={}", key, value));
    }
  }
}

} // namespace

/// Arguments after expanding `--config FILE` (or --config=FILE) of the evolve subcommand into
/// `--key=value` arguments placed before the command line's own, so that flags override the
/// file. CLI11 2.1 does not read config files given to a subcommand, hence this step; the file
/// is parsed by CLI11's own TOML/INI reader. Throws ParamError for a missing file or a key that
/// names no parameter.
std::vector<std::string> expand_config(const std::vector<std::string>& args,
                                       std::map<std::string, std::string>* origins) {
  std::vector<std::string> rest, from_file;
  std::map<std::string, std::string> file_of; // flag -> the file that gave it
  for (std::size_t k = 0; k < args.size(); ++k) {
    std::string path;
    if (args[k] == "--config") {
      if (k + 1 >= args.size())
        throw ParamError("--config", "''", "needs a file name");
      path = args[++k];
    } else if (args[k].rfind("--config=", 0) == 0) {
      path = args[k].substr(9);
    } else {
      rest.push_back(args[k]);
      continue;
    }
    read_config_args(path, from_file, file_of);
  }
  if (origins) {
    // a flag on the command line overrides the file's value: its errors are the command line's
    for (const auto& a : rest)
      file_of.erase(a.substr(0, a.find('=')));
    *origins = std::move(file_of);
  }
  // the subcommand name stays first
  std::vector<std::string> out;
  if (!rest.empty())
    out.push_back(rest.front());
  out.insert(out.end(), from_file.begin(), from_file.end());
  if (rest.size() > 1)
    out.insert(out.end(), rest.begin() + 1, rest.end());
  return out;
}

const std::map<std::string, std::string>& absent_key_values() {
  static const std::map<std::string, std::string> values{{"box-taper", "0"}, {"kappa1-hole", "0"}};
  return values;
}

namespace {

/// The absent keys that stand for their value only in configurations holding another key's
/// value (kappa1-hole: Z4c's; BSSN's never write it, so that its absence there means nothing).
const std::map<std::string, std::pair<std::string, std::string>>& absent_key_conditions() {
  static const std::map<std::string, std::pair<std::string, std::string>> conditions{
      {"kappa1-hole", {"formulation", "\"z4c\""}}};
  return conditions;
}

} // namespace

namespace {

/// The "key = value" lines of a configuration text ('#' lines skipped), but the `ignored` keys.
std::map<std::string, std::string> key_values(const std::string& text,
                                              const std::vector<std::string>& ignored = {}) {
  std::map<std::string, std::string> kv;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find(" = ");
    if (line.empty() || line[0] == '#' || eq == std::string::npos)
      continue;
    const std::string key = line.substr(0, eq);
    if (std::find(ignored.begin(), ignored.end(), key) == ignored.end())
      kv[key] = line.substr(eq + 3);
  }
  return kv;
}

} // namespace

std::vector<std::string> absent_key_args(const std::string& text) {
  const auto kv = key_values(text);
  std::vector<std::string> args;
  for (const auto& [key, value] : absent_key_values()) {
    const auto condition = absent_key_conditions().find(key);
    const bool applies = condition == absent_key_conditions().end()
                         || (kv.contains(condition->second.first)
                             && kv.at(condition->second.first) == condition->second.second);
    if (!kv.contains(key) && applies)
      args.push_back(fmt::format("--{}={}", key, value));
  }
  return args;
}

std::vector<std::string> config_differences(const std::string& old_text,
                                            const std::string& new_text,
                                            const std::vector<std::string>& ignored) {
  const auto a = key_values(old_text, ignored), b = key_values(new_text, ignored);
  // a key missing from a text written before its parameter existed stands for what runs did
  // then: its absent_key_values() entry, else its default
  static const auto defaults = [] {
    auto d = key_values(config_text(Params{}));
    for (const auto& [key, value] : absent_key_values())
      d[key] = value;
    return d;
  }();
  std::vector<std::string> diff;
  auto value_of = [](const std::map<std::string, std::string>& kv, const std::string& key) {
    if (const auto it = kv.find(key); it != kv.end())
      return it->second;
    const auto d = defaults.find(key);
    return d == defaults.end() ? std::string("(unset)") : d->second;
  };
  std::set<std::string> keys;
  for (const auto* kv : {&a, &b})
    for (const auto& [key, value] : *kv)
      keys.insert(key);
  for (const auto& key : keys)
    if (value_of(a, key) != value_of(b, key))
      diff.push_back(fmt::format("{}: {} -> {}", key, value_of(a, key), value_of(b, key)));
  return diff;
}

bool is_parameter_name(const std::string& name) {
  return std::any_of(param_specs().begin(), param_specs().end(),
                     [&](const ParamSpec& s) { return name == s.name; });
}

Params parse_evolve_args(const std::vector<std::string>& args) {
  std::vector<std::string> expanded{"evolve"};
  expanded.insert(expanded.end(), args.begin(), args.end());
  expanded = expand_config(expanded);
  expanded.erase(expanded.begin());
  CLI::App app{"evolve"};
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  Params p;
  add_options(app, p);
  std::reverse(expanded.begin(), expanded.end());
  try {
    app.parse(expanded);
  } catch (const CLI::ParseError& e) {
    // converge and sweep pass their other flags on to evolve: one that evolve does not know, or
    // a value it cannot take, is invalid input (exit status 2) naming it, as in evolve itself
    for (const auto& a : args)
      if (a.size() > 2 && a.rfind("--", 0) == 0) {
        const std::string name = a.substr(2, a.find('=') - 2);
        if (!is_parameter_name(name) && name != "config")
          throw ParamError("--" + printable(name),
                           "is not an evolve flag (`gbssn1d evolve --help` lists them)");
      }
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    throw ParamError("argument", printable(what));
  }
  return p;
}

} // namespace gbssn1d
