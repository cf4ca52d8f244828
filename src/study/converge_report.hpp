// A converge study's results: how it ended, its verdict (study/verdict.hpp), convergence.dat
// (norms and orders over the common times) and scaled_H.dat (Richardson-scaled H profiles).
#pragma once

#include "config/params.hpp"
#include "core/registry.hpp"
#include "study/converge.hpp"
#include "study/converge_records.hpp"
#include "study/verdict.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace gbssn1d {

/// A coordinate interval [lo, hi].
struct Extent {
  double lo = 0.0, hi = 0.0;
};

/// A member's composite cells, where its round-off floor is estimated (verdict.hpp,
/// round_off_floor): the coordinate r and width dr of each interior point, and the coordinate
/// extent of each place a judged quantity is taken over.
struct MemberCells {
  std::vector<double> r, dr;
  double dr_min = 0.0; ///< the smallest cell width anywhere (its finest level's; dr-min)
  Extent ext;          ///< the coordinate window of the *_ext norms
  Extent areal;        ///< the points of the areal window on the member's initial data
  Extent samples;      ///< the radii the --fields are sampled at
  /// The smallest width of the cells within kSignalSpeed t of e: those whose round-off can have
  /// reached a quantity taken over e by time t (at t = 0 the cells of e alone).
  double reach(const Extent& e, double t) const;
};

/// A study as run: its members, what each samples (the fields at the common radii: the
/// coarsest member's exterior points), what each recorded, and each one's cells.
struct ConvergeStudy {
  const Params& base;
  const ConvergeOptions& options;
  std::vector<ResolvedParams> members;
  std::vector<double> radii;
  std::vector<Var> fields;
  std::string samples_key; ///< saved samples are reused only for the same key
  std::vector<MemberRecord> records;
  std::size_t n_times = 0; ///< output times common to all members
  /// each member's cells, which set its round-off floor where each quantity is taken
  std::vector<MemberCells> cells;
  double Nd(std::size_t k) const { return static_cast<double>(members[k].N); }
};

/// How the study ended, in both files' headers and as their last line: a reader (and a plot
/// script) must be able to tell a partial study from a complete one.
struct StudyEnding {
  int signal = 0;            ///< the stop signal, 0 if none
  std::string failed;        ///< the first member's failure, empty if none
  bool write_failed = false; ///< a member's failure was a write (exit 1, not judged)
  double t_common = 0.0;
  std::string ending, status_line, end_line;
};
StudyEnding study_ending(const ConvergeStudy& s);

/// The verdict and its texts: `judged` (the finding), `verdict_text` (with failures and
/// interruptions), the `order` lines of convergence.dat's header.
struct StudyVerdict {
  Verdict verdict;
  ConvergenceClass kind = ConvergenceClass::converges; ///< the study's class (verdict.hpp)
  bool converges = true; ///< classes 1 and 2: every judged order meets the threshold
  std::string judged, verdict_text, order_lines;
};
StudyVerdict judge_study(const ConvergeStudy& s, const StudyEnding& e);

/// Every judged norm at each pair of neighbouring members and every field's differences at
/// each triple, over the common times, with the round-off floor of the finest member involved:
/// what judge_study() (converge_verdict.cpp) judges.
std::vector<OrderSeries> order_series(const ConvergeStudy& s);

void write_convergence_dat(const ConvergeStudy& s, const std::string& base_config,
                           const StudyEnding& e, const StudyVerdict& v);
void write_scaled_H(const ConvergeStudy& s, const std::string& base_config, const StudyEnding& e);

} // namespace gbssn1d
