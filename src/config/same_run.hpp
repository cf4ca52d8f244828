// One notion of "the same run" (docs/design.md): the effective configuration of a run, which
// leaves out the flags that do nothing in it, and those flags, for warnings and study notes.
// Where each flag acts is its row of the flag table (config/flag_table.*).
#pragma once

#include "config/params.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace gbssn1d {

/// Flags given a value (other than the one an unset flag resolves to) in a configuration where
/// they do nothing, grouped by why: e.g. because "with --rahA 0", flags {"rah0"}, given
/// {"--rah0 0.6"}, and what to do instead. Each flag's table entry says where it acts
/// (config_file.cpp).
struct IdleFlags {
  std::string because;
  std::string instead;            ///< what they need to act, or what to do instead
  std::vector<std::string> flags; ///< their names, without "--"
  std::vector<std::string> given; ///< "--name value" as on a command line
  /// The warning a run gives (config/params.hpp: warnings()): "--rah0 0.6 does nothing with
  /// --rahA 0: ..."
  std::string warning() const;
};
std::vector<IdleFlags> idle_flags(const ResolvedParams& p);

/// The effective configuration of resolved parameters: `p` with every flag
/// that does nothing in it at the value an unset flag resolves to, and without --out and
/// --force. It is what decides a run's outputs.
Params effective(const ResolvedParams& p);

/// The one notion of "the same run": two resolved parameter sets are the same run (the same
/// outputs but for the folder's name) exactly when their keys are equal. config_text() of the
/// effective configuration.
std::string run_key(const ResolvedParams& p);

/// The keys of resolved parameters whose values are what their rules give for the others (eta
/// 2/M, Z4c's kappa1 0.02/M and kappa1-hole 1/M, norm-rmax, levels, box-taper, rah-rcut,
/// rah-taper, and rah-profile with rah-width as auto chooses them): what a run did not give.
std::vector<std::string> rule_valued_keys(const Params& p);
/// Every key a rule gives (the candidates of rule_valued_keys()).
const std::vector<std::string>& rule_keys();

/// The line config.toml carries after its keys, naming rule_valued_keys() ("" for none): a
/// configuration read back (`--config`, resume) leaves those keys to their rules again, so that
/// a value a run never gave is neither a flag given (an idle-flag warning with another
/// --formulation) nor kept where the inputs its rule reads have changed.
std::string rule_values_line(const Params& p);
inline constexpr std::string_view rule_values_mark = "# rule values, not given: ";

} // namespace gbssn1d
