// `gbssn1d sweep`: the Cartesian product of value lists for any flags, each member an
// `evolve` subprocess in its own directory named by its values; a summary table; resumable.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace gbssn1d {

/// One axis of the product. Several flags may vary together along one axis:
/// "N,dr-inner=400:0.02,800:0.01" (values of one member joined by ':').
struct SweepAxis {
  std::vector<std::string> flags;               ///< without "--"
  std::vector<std::vector<std::string>> values; ///< per point of the axis, one per flag
};

/// "rahA=0,0.25,0.5" -> {{rahA}, {{0}, {0.25}, {0.5}}}; throws ParamError naming --sweep.
SweepAxis parse_sweep_axis(const std::string& text);

struct SweepMember {
  std::string name; ///< directory name, e.g. rahA=0.25_rah0=0.6
  std::vector<std::pair<std::string, std::string>> values;
  std::vector<std::string> args; ///< evolve arguments, --out included
  /// Its effective configuration (defaults resolved; its arguments if they do not parse): what
  /// a rerun of the sweep is compared against.
  std::string inputs;
  /// Its run key (config/config_file.hpp: run_key(), the effective configuration without the
  /// flags that do nothing in it): members with equal keys are the same run. Its arguments if
  /// they do not parse.
  std::string run_key;
  /// The flags it gives where they do nothing (config/config_file.hpp: idle_flags()): each
  /// warning its run gives about them, with the flags that warning names.
  struct Idle {
    std::string warning;
    std::vector<std::string> flags;
  };
  std::vector<Idle> idle;
  /// Its end time (its --tmax, defaults resolved): where the end line of its timeseries.dat
  /// says a completed run ended; nothing if its arguments do not parse.
  std::optional<double> tmax;
};

/// A member's folder name from its (flag, value) pairs: "flag=value_flag=value", with '/' and
/// ' ' as '_'.
std::string member_name(const std::vector<std::pair<std::string, std::string>>& values);

/// The members of the product, in order (the last axis varies fastest). With `only`, just the
/// member of that name (none if there is no such member), its folder name checked against the
/// others' but its inputs alone computed: a task line's work is its member's, not the sweep's.
std::vector<SweepMember> sweep_members(const std::vector<SweepAxis>& axes,
                                       const std::vector<std::string>& evolve_args,
                                       const std::string& out, const std::string& only = "");

/// A finished member whose H_L2_R_max exceeds this many times the median of its neighbours
/// along an axis is flagged `spike` in summary.dat (and named on stderr).
inline constexpr double kSpikeFactor = 100.0;

/// Most members a sweep takes (a product of value lists grows fast: 100 x 100 x 100 would be
/// a million processes); more is refused before anything is made.
inline constexpr std::size_t kMembersMax = 10000;

struct SweepOptions {
  std::vector<std::string> sweeps; ///< the --sweep arguments
  int jobs = 1;
  std::string out;
  std::string emit_tasks;       ///< write the member command lines here instead of running
  std::string member;           ///< run only this member (what an emitted line does)
  bool collect = false;         ///< build summary.dat from the members, run nothing
  double progress_every = 60.0; ///< seconds between progress lines while members run (0: none)
};

/// Runs (or resumes) the sweep and writes DIR/summary.dat: 0 when every member finished, 3
/// when any blew up, failed or was invalid (marked in the summary), 2 for bad sweep arguments.
/// With `member`, runs that member alone; with `collect`, only writes summary.dat (1 when
/// members have not run yet); with `emit_tasks`, writes one command line per valid member.
int run_sweep(const SweepOptions& options, const std::vector<std::string>& evolve_args);

} // namespace gbssn1d
