#include "study/converge_report.hpp"

#include "core/console.hpp"
#include "core/stop_signal.hpp"

#include "core/registry.hpp"
#include "io/output.hpp"
#include "study/orders.hpp"
#include "study/verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <optional>
#include <set>

#include <iterator>

namespace gbssn1d {

namespace fs = std::filesystem;

namespace {

/// The norms compared across members: column stem, order stem, value (judged: part of the
/// verdict; length_power: the quantity's scale is M^length_power, 1/M^2 for H and M_r, 1/M for
/// G^r, of which round_off_floor(M, dr) is round-off; window: where it is taken, whose cells set
/// that floor).
struct Norm {
  const char *column, *order;
  double SeriesRow::*value;
  bool judged;
  int length_power;
  Extent MemberCells::*window;
};
const Norm bssn_norms[] = {{"H_L2_ext", "H", &SeriesRow::H_L2_ext, true, -2, &MemberCells::ext},
                           {"M_L2_ext", "M", &SeriesRow::M_L2_ext, true, -2, &MemberCells::ext},
                           {"G_L2_ext", "G", &SeriesRow::G_L2_ext, true, -1, &MemberCells::ext},
                           {"H_L2_R", "H_R", &SeriesRow::H_L2_R, true, -2, &MemberCells::areal},
                           {"M_L2_R", "M_R", &SeriesRow::M_L2_R, true, -2, &MemberCells::areal},
                           {"H_L2_int", "H_int", &SeriesRow::H_L2_int, false, -2, nullptr}};
/// A formulation's own series columns that a study judges like the rest (Z4c's, Sec. 17: G^r
/// and Theta, a curvature, 1/M^2, in the areal window); each is judged where the formulation
/// writes it (FormulationTraits::extra_series).
const Norm own_norms[] = {
    {"G_L2_R", "G_R", &SeriesRow::G_L2_R, true, -1, &MemberCells::areal},
    {"Theta_L2_R", "Theta_R", &SeriesRow::Theta_L2_R, true, -2, &MemberCells::areal}};

/// The norms of a study of `formulation`.
std::vector<Norm> study_norms(Formulation formulation) {
  std::vector<Norm> n(std::begin(bssn_norms), std::end(bssn_norms));
  const auto& own = traits(formulation).extra_series;
  for (const Norm& c : own_norms)
    if (std::find(own.begin(), own.end(), c.column) != own.end())
      n.push_back(c);
  return n;
}

} // namespace

/// Every judged norm at each pair of neighbouring members and every field's differences at
/// each triple, over the common times, with the round-off floor of the finest member involved
/// where the quantity is taken.
std::vector<OrderSeries> order_series(const ConvergeStudy& s) {
  const auto& [base, options, members, radii, fields, samples_key, records, n_times, cells] = s;
  const std::size_t m = members.size();
  const auto Nd = [&](std::size_t k) { return s.Nd(k); };
  std::vector<OrderSeries> series;
  for (const auto& c : study_norms(base.formulation.value())) {
    if (!c.judged)
      continue;
    for (std::size_t k = 0; k + 1 < m; ++k) {
      OrderSeries s{c.column, {Nd(k), Nd(k + 1)}, {}, {}, {}};
      for (std::size_t q = 0; q < n_times; ++q) {
        s.coarse.push_back(records[k].rows[q].*c.value);
        s.fine.push_back(records[k + 1].rows[q].*c.value);
        const MemberCells& finer = cells[k + 1];
        s.floor.push_back(
            round_off_floor(base.M, finer.reach(finer.*c.window, records[k].rows[q].t))
            * std::pow(base.M, c.length_power));
      }
      series.push_back(std::move(s));
    }
  }
  for (std::size_t f = 0; f < fields.size(); ++f)
    for (std::size_t k = 0; k + 2 < m; ++k) {
      OrderSeries s{options.fields[f], {Nd(k), Nd(k + 1), Nd(k + 2)}, {}, {}, {}, false};
      const std::size_t off = f * radii.size();
      const std::vector<double> zeros(off + radii.size(), 0.0);
      for (std::size_t q = 0; q < n_times; ++q) {
        const auto& a = records[k].field_samples[q];
        const auto& b = records[k + 1].field_samples[q];
        const auto& c = records[k + 2].field_samples[q];
        s.coarse.push_back(rms_difference(a, b, off, radii.size()));
        s.fine.push_back(rms_difference(b, c, off, radii.size()));
        // the field's scale: the RMS of the triple's coarsest member's values at the radii; at
        // t = 0 the members start from the same data and differ by the 6th-order interpolation
        // onto the coarsest radii alone, which the three-level formula does not describe: not
        // judged
        s.floor.push_back(records.front().rows[q].t == 0.0
                              ? std::numeric_limits<double>::infinity()
                              : round_off_floor(base.M, cells[k + 2].reach(cells[k + 2].samples,
                                                                           records[k].rows[q].t))
                                    * rms_difference(a, zeros, off, radii.size()));
      }
      series.push_back(std::move(s));
    }
  return series;
}

double MemberCells::reach(const Extent& e, double t) const {
  const double lo = e.lo - kSignalSpeed * t, hi = e.hi + kSignalSpeed * t;
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.size(); ++i)
    if (r[i] >= lo && r[i] <= hi)
      smallest = std::min(smallest, dr[i]);
  return std::isfinite(smallest) ? smallest : dr_min;
}

StudyEnding study_ending(const ConvergeStudy& s) {
  const auto& members = s.members;
  const auto& records = s.records;
  const std::size_t m = members.size(), n_times = s.n_times;
  StudyEnding e;
  e.signal = stop_signal();
  const int signal = e.signal;
  std::string& failed = e.failed;
  for (std::size_t k = 0; k < m; ++k)
    if (!records[k].error.empty() && failed.empty())
      failed = fmt::format("member N = {} failed: {}", members[k].N, records[k].error);
  for (std::size_t k = 0; k < m; ++k)
    e.write_failed = e.write_failed || records[k].write_failed;
  e.t_common = n_times > 0 ? records.front().rows[n_times - 1].t : 0.0;
  e.ending =
      signal != 0 ? fmt::format("interrupted by {} at t = {} (partial: every member only to this "
                                "time; rerun the same command to resume)",
                                signal_name(signal), e.t_common)
      : !failed.empty()
          ? fmt::format("stopped: {} (partial: common times up to t = {})", failed, e.t_common)
          : fmt::format("completed at t = {}", e.t_common);
  e.status_line = fmt::format("status: {}\n", e.ending);
  e.end_line = fmt::format("# end: {}\n", e.ending);

  return e;
}

void write_convergence_dat(const ConvergeStudy& s, const std::string& base_config,
                           const StudyEnding& e, const StudyVerdict& v) {
  const auto& [base, options, members, radii, fields, samples_key, records, n_times, cells] = s;
  const std::size_t m = members.size();
  const auto Nd = [&](std::size_t k) { return s.Nd(k); };
  const std::string& status_line = e.status_line;
  const std::string& end_line = e.end_line;
  const std::string& order_lines = v.order_lines;
  const std::vector<Norm> norms = study_norms(base.formulation.value());
  const int n_norms = static_cast<int>(norms.size());
  std::vector<std::string> cols{"t"};
  for (const auto& c : norms)
    for (std::size_t k = 0; k < m; ++k)
      cols.push_back(fmt::format("{}_N{}", c.column, members[k].N));
  for (const auto& c : norms)
    for (std::size_t k = 0; k + 1 < m; ++k)
      cols.push_back(fmt::format("p_{}_{}_{}", c.order, members[k].N, members[k + 1].N));
  for (const auto& name : options.fields)
    for (std::size_t k = 0; k + 2 < m; ++k)
      cols.push_back(
          fmt::format("p3_{}_{}_{}_{}", name, members[k].N, members[k + 1].N, members[k + 2].N));

  const std::string header =
      base_config + status_line + order_lines
      + fmt::format("converge: N = {}; p_X_a_b = ln(X_a/X_b)/ln(b/a) of the norms (X_L2_ext: "
                    "coordinate window, X_L2_R: areal window, H_L2_int: near the puncture); "
                    "p3_f_a_b_c solves |f_a - f_b|/|f_b - f_c| = (a^-p - b^-p)/(b^-p - c^-p) "
                    "(Sec. 15) with RMS differences of f at the coarsest grid's radii in "
                    "[norm-rmin, norm-rmax] (6th-order interpolation)\n",
                    fmt::join(options.N, ","));
  {
    DataFile file(fs::path(options.out) / "convergence.dat", header, cols);
    for (std::size_t s = 0; s < n_times; ++s) {
      std::string line = time_text(records.front().rows[s].t);
      auto norm = [&](std::size_t k, int c) { return records[k].rows[s].*norms[c].value; };
      for (int c = 0; c < n_norms; ++c)
        for (std::size_t k = 0; k < m; ++k)
          line += fmt::format(" {:.16e}", norm(k, c));
      for (int c = 0; c < n_norms; ++c)
        for (std::size_t k = 0; k + 1 < m; ++k)
          line +=
              fmt::format(" {:.6e}", order_two_level(norm(k, c), norm(k + 1, c), Nd(k), Nd(k + 1)));
      for (std::size_t f = 0; f < fields.size(); ++f)
        for (std::size_t k = 0; k + 2 < m; ++k) {
          const auto& a = records[k].field_samples[s];
          const auto& b = records[k + 1].field_samples[s];
          const auto& c = records[k + 2].field_samples[s];
          const std::size_t off = f * radii.size();
          line += fmt::format(" {:.6e}", order_three_level(rms_difference(a, b, off, radii.size()),
                                                           rms_difference(b, c, off, radii.size()),
                                                           Nd(k), Nd(k + 1), Nd(k + 2)));
        }
      line += "\n";
      file.write(line.data(), line.size());
    }
    file.write(end_line.data(), end_line.size());
    file.flush(); // checked: a failed write throws OutputError
  }
}

void write_scaled_H(const ConvergeStudy& s, const std::string& base_config, const StudyEnding& e) {
  const auto& [base, options, members, radii, fields, samples_key, records, n_times, cells] = s;
  const std::size_t m = members.size();
  const auto Nd = [&](std::size_t k) { return s.Nd(k); };
  const std::string& status_line = e.status_line;
  const std::string& end_line = e.end_line;
  // scaled_H.dat: H at the common radii, finer members times (N_k/N_0)^order
  {
    std::vector<std::string> scols{"r"};
    for (std::size_t k = 0; k < m; ++k)
      scols.push_back(k == 0 ? fmt::format("H_N{}", members[k].N)
                             : fmt::format("H_N{}_scaled", members[k].N));
    DataFile file(fs::path(options.out) / "scaled_H.dat",
                  base_config + status_line
                      + fmt::format("scaled_H.dat: H of member N_k times (N_k/N_0)^{} "
                                    "at the coarsest grid's exterior radii\n",
                                    options.order),
                  scols);
    std::vector<double> times = options.scaled_times;
    if (times.empty())
      times.push_back(base.tmax);
    bool first = true;
    std::set<std::size_t> written; // output rows with a block: each once
    for (double tw : times) {
      if (n_times == 0)
        break;
      std::size_t s = 0;
      for (std::size_t q = 0; q < n_times; ++q)
        if (std::abs(records.front().rows[q].t - tw) < std::abs(records.front().rows[s].t - tw))
          s = q;
      const double t_row = records.front().rows[s].t, t_last = records.front().rows[n_times - 1].t;
      const double tol = 1e-9 * std::max(1.0, std::abs(tw));
      // the time asked for (tmax when none is given)
      const std::string asked =
          options.scaled_times.empty()
              ? fmt::format("the scaled profiles' time, tmax = {}", time_text(tw))
              : fmt::format("--scaled-times {}", time_text(tw));
      if (tw > t_last + tol)
        say("gbssn1d converge: note: {} lies beyond the common times, which end at t = {} ({}): "
            "its block is the last common row's\n",
            asked, time_text(t_last),
            e.signal != 0       ? "the study was interrupted; rerun it to complete"
            : !e.failed.empty() ? e.failed
                                : "a member's rows end there");
      else if (std::abs(t_row - tw) > tol)
        say("gbssn1d converge: note: {} is no output time (rows every --dt-series {}): its block "
            "is the nearest row's, t = {}\n",
            asked, time_text(base.dt_series), time_text(t_row));
      if (!written.insert(s).second) {
        say("gbssn1d converge: note: --scaled-times {} falls on the output at t = {}, which has "
            "its block already (one block per output time)\n",
            time_text(tw), time_text(records.front().rows[s].t));
        continue;
      }
      std::string block = first ? "" : "\n\n";
      first = false;
      block += "# t = " + time_text(records.front().rows[s].t) + "\n";
      for (std::size_t j = 0; j < radii.size(); ++j) {
        block += fmt::format("{:.16e}", radii[j]);
        for (std::size_t k = 0; k < m; ++k)
          block += fmt::format(" {:.16e}",
                               records[k].H_samples[s][j] * std::pow(Nd(k) / Nd(0), options.order));
        block += "\n";
      }
      file.write(block.data(), block.size());
    }
    file.write(end_line.data(), end_line.size());
    file.flush();
  }
}

} // namespace gbssn1d
