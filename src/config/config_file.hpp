// The run parameters as text: one table of every evolve flag (name, member of Params, group,
// help) drives the CLI11 options, the `key = value` configuration files and their reading back,
// so that the command line and config.toml cannot drift apart.
#pragma once

#include "config/params.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace gbssn1d {

/// Adds every evolve flag, grouped, with its default, to `app`, bound to `p`.
void add_options(CLI::App& app, Params& p);

/// A numeric option of a subcommand (e.g. "-j,--jobs") read by the one number reader
/// (config/numbers.hpp); a bad value is a ParamError naming the option's first name. The
/// default shown by --help is the target's value.
CLI::Option* add_number_option(CLI::App& app, const std::string& names, int& target,
                               const std::string& help);
CLI::Option* add_number_option(CLI::App& app, const std::string& names, double& target,
                               const std::string& help);

/// The effective configuration as a TOML/INI file that `evolve --config` reads back: one
/// `key = value` line per parameter, at full precision.
std::string config_text(const Params& p);

/// Keys added with a default that is not what runs recorded before them did: in a recorded
/// configuration that lacks one, its absence means this value (e.g. box-taper = 0: boxes
/// without the tapered buffer), not today's default.
const std::map<std::string, std::string>& absent_key_values();
/// "--key=value" for each key of absent_key_values() that the recorded configuration `text`
/// lacks: appended to a parse of that text, they give the run it recorded.
std::vector<std::string> absent_key_args(const std::string& text);

/// The parameters whose values differ between two configuration texts (config.toml), as
/// "key: old -> new"; a key missing on one side stands for its absent_key_values() entry or
/// its default (a text written before that parameter existed), or reads "(unset)" if it has
/// none; '#' lines and the keys in `ignored` are not compared.
std::vector<std::string>
config_differences(const std::string& old_text, const std::string& new_text,
                   const std::vector<std::string>& ignored = {"out", "force"});

/// Arguments after expanding `--config FILE` into `--key=value` arguments placed before the
/// command line's own, so that flags override the file. Throws ParamError for a missing file,
/// a key that names no parameter or a bad boolean. `origins` (if given) gets, for each flag whose
/// value comes from a file (not overridden on the command line), that file: "--N" -> "run.toml".
std::vector<std::string> expand_config(const std::vector<std::string>& args,
                                       std::map<std::string, std::string>* origins = nullptr);

/// A string as a TOML basic string ("...", with '"', '\\' and control characters escaped), as
/// config_text() writes string values; read_config_text() reads it back exactly.
std::string toml_string(const std::string& s);

/// The `key = value` items of a configuration file's text, in order: comments ('#') and blank
/// lines skipped; values bare (numbers, true/false) or quoted ("..." with escapes, '...'
/// literal). Throws ParamError (--config, `path`, the line) for a section, a key given twice, a
/// line that is not `key = value`, an array or an unclosed string. Keys are not checked here.
std::vector<std::pair<std::string, std::string>> read_config_text(const std::string& text,
                                                                  const std::string& path);

/// Parameters from evolve flags (`--config` files expanded), e.g. a sweep member's arguments.
/// Throws ParamError or CLI::ParseError. Does not resolve defaults or validate.
Params parse_evolve_args(const std::vector<std::string>& args);

/// Whether `name` (without "--") is an evolve flag.
bool is_parameter_name(const std::string& name);

} // namespace gbssn1d
