// A sweep's members as stored in its folder OUT: their names and inputs, the status file each
// run leaves in OUT/logs/, which members are done for good, which are the same run, and the
// checks that a rerun, --member or --collect meets the same members with the same inputs.
#pragma once

#include "study/sweep.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gbssn1d {

/// A member's status file, "status wall reason", as a rerun of the sweep reads it back.
struct RecordedStatus {
  std::string status, reason;
  double wall = 0.0;
};
std::optional<RecordedStatus> recorded_status(const std::filesystem::path& status_file);

/// Whether a member is done for good: finished (ok), or ended by its inputs (invalid, blew-up),
/// which a rerun would only repeat. A member that failed (a write error, killed by a signal of
/// its own such as the kernel's out-of-memory SIGKILL) or was interrupted is not: a rerun of
/// the sweep, or its requeued task line, runs it again, from its checkpoint where it has one.
/// A missing, empty or broken status file counts as not done, and so does a member recorded
/// ok or blew-up whose output is not there (member_output_problem): its folder deleted, its
/// timeseries.dat missing or cut short.
bool member_done(const std::filesystem::path& dir, const SweepMember& m);

/// Why the output of member `m` of the sweep in `dir`, recorded with `status`, is not what
/// that status says it wrote (ok: a timeseries.dat whose last line is a whole "# end:
/// completed at t = T" line, T the member's tmax; blew-up: one whose last line is a whole
/// "# end: stopped" line), or nothing when it is (or the status writes no output). A line is
/// whole with its line end; a file cut anywhere in its end line is cut short.
std::optional<std::string> member_output_problem(const std::filesystem::path& dir,
                                                 const SweepMember& m, const std::string& status);

/// `s` as one word of a status file or summary.dat: blanks as '_', empty as '-'.
std::string token(std::string s);

/// Members that are the same run (equal run keys: they differ only in flags that do nothing
/// in them, e.g. rah0 with rahA = 0): their names and the flags they differ in.
struct SameRun {
  std::vector<std::string> members;
  std::vector<std::string> flags;
  /// "a = b = c are the same run (rah0 does nothing there)": said on stderr and in summary.dat, so
  /// that nobody reads them as different results.
  std::string text() const;
};
std::vector<SameRun> same_runs(const std::vector<SweepMember>& members);

/// Why `m` cannot run (its flags do not validate), or nullopt.
std::optional<std::string> invalid_reason(const SweepMember& m);

/// A folder that holds members run with other inputs is refused (naming them) before anything
/// is written or launched: results of other inputs are never reused or mixed in. A member's
/// inputs are read from logs/NAME.inputs, and its folder's own config.toml (and its copy of
/// --rah-hAH-file) must agree with them too: a folder replaced by another run is not the
/// member, whatever its status file says.
void check_earlier_inputs(const std::filesystem::path& dir,
                          const std::vector<const SweepMember*>& members, const std::string& out);
std::vector<const SweepMember*> all_of(const std::vector<SweepMember>& members);

/// A sweep writes no file through a symbolic link: a member folder (or logs/, a member's log,
/// status, inputs or lock file, summary.dat, logs/axes) that is a link would send the member's
/// run, or its record, to what the link points at (another run's folder overwritten, or
/// reported as the member). Refused, naming the link, before anything is written.
void refuse_links(const std::filesystem::path& dir, const std::vector<const SweepMember*>& members,
                  const std::string& out);

/// The sweep's axes in their order, recorded in OUT/logs/axes: member folders are named in
/// that order, so a rerun, --member or --collect with the axes in another order would find
/// none of them. check_axis_order refuses axes in another order than the folder's sweep (or
/// other axes), naming its order.
void record_axis_order(const std::string& out, const std::vector<SweepAxis>& axes);
void check_axis_order(const std::string& out, const std::vector<SweepAxis>& axes);

/// Refuses (ParamError naming --out) a folder that holds another command's output: an evolve
/// run's or a converge study's config.toml at its top.
void refuse_other_commands_folder(const std::string& out);

} // namespace gbssn1d
