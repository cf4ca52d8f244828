#include "study/converge.hpp"

#include "core/console.hpp"
#include "core/stop_signal.hpp"

#include "config/config_file.hpp"
#include "config/params.hpp"
#include "core/registry.hpp"
#include "evolution/simulation.hpp"
#include "grid/interpolation.hpp"
#include "io/output.hpp"
#include "study/orders.hpp"
#include "study/parallel.hpp"
#include "study/verdict.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <optional>

namespace gbssn1d {

namespace fs = std::filesystem;

namespace {

/// What one member records at every series output.
struct MemberRecord {
  std::vector<SeriesRow> rows;
  std::vector<std::vector<double>> field_samples; ///< per output: fields x common radii
  std::vector<std::vector<double>> H_samples;     ///< per output: H at the common radii
  std::string error;                              ///< non-empty if the member failed
};

/// A member's samples saved with each of its checkpoints (DIR/N<n>/converge_samples.bin), so
/// that a rerun of the study continues the member from the checkpoint: what was sampled (`key`:
/// the fields and the radii, which depend on the study's coarsest member), the step they belong
/// to, then the rows and the samples, each list as a count and raw doubles. Samples of another
/// key are never reused.
void write_samples(const fs::path& file, const std::string& key, std::int64_t step,
                   const MemberRecord& rec) {
  std::string blob;
  auto put = [&](const void* p, std::size_t n) { blob.append(static_cast<const char*>(p), n); };
  const std::uint64_t rows = rec.rows.size(), key_size = key.size();
  put(&key_size, sizeof(key_size));
  put(key.data(), key.size());
  put(&step, sizeof(step));
  put(&rows, sizeof(rows));
  put(rec.rows.data(), rows * sizeof(SeriesRow));
  for (const auto* list : {&rec.field_samples, &rec.H_samples})
    for (const auto& v : *list) {
      const std::uint64_t n = v.size();
      put(&n, sizeof(n));
      put(v.data(), n * sizeof(double));
    }
  write_file_atomically(file, blob);
}

/// The samples saved with the checkpoint at `step`, or nothing (missing, other step, broken).
std::optional<MemberRecord> read_samples(const fs::path& file, const std::string& key,
                                         std::int64_t step) {
  std::ifstream in(file, std::ios::binary);
  auto get = [&](void* p, std::size_t n) {
    return static_cast<bool>(in.read(static_cast<char*>(p), static_cast<std::streamsize>(n)));
  };
  std::uint64_t key_size = 0;
  if (!get(&key_size, sizeof(key_size)) || key_size != key.size())
    return std::nullopt;
  std::string saved_key(key_size, '\0');
  if (!get(saved_key.data(), key_size) || saved_key != key)
    return std::nullopt;
  std::int64_t saved_step = -1;
  std::uint64_t rows = 0;
  if (!get(&saved_step, sizeof(saved_step)) || saved_step != step || !get(&rows, sizeof(rows))
      || rows > (1u << 26))
    return std::nullopt;
  MemberRecord rec;
  rec.rows.resize(rows);
  if (!get(rec.rows.data(), rows * sizeof(SeriesRow)))
    return std::nullopt;
  for (auto* list : {&rec.field_samples, &rec.H_samples}) {
    list->resize(rows);
    for (auto& v : *list) {
      std::uint64_t n = 0;
      if (!get(&n, sizeof(n)) || n > (1u << 26))
        return std::nullopt;
      v.resize(n);
      if (!get(v.data(), n * sizeof(double)))
        return std::nullopt;
    }
  }
  return rec;
}

double rms_difference(const std::vector<double>& a, const std::vector<double>& b,
                      std::size_t offset, std::size_t count) {
  double sum = 0.0;
  for (std::size_t j = offset; j < offset + count; ++j)
    sum += (a[j] - b[j]) * (a[j] - b[j]);
  return std::sqrt(sum / static_cast<double>(count));
}

} // namespace

std::vector<Params> converge_members(const Params& base, const ConvergeOptions& options) {
  if (options.N.size() < 3)
    throw ParamError("--N", fmt::format("{}", fmt::join(options.N, ",")),
                     "needs at least three resolutions");
  for (std::size_t k = 1; k < options.N.size(); ++k)
    if (!(options.N[k] > options.N[k - 1]))
      throw ParamError("--N", fmt::format("{}", fmt::join(options.N, ",")),
                       "resolutions must increase");
  for (const auto& name : options.fields)
    if (!var_from_name(name))
      throw ParamError("--fields", name, "is not an evolved variable");
  std::vector<Params> members;
  for (int n : options.N) {
    Params p = base;
    p.N = n; // the map does not depend on N, so this is a refinement on either grid
    p.out = (fs::path(options.out) / fmt::format("N{}", n)).string();
    p.force = true;
    resolve_defaults(p);
    validate(p);
    members.push_back(p);
  }
  return members;
}

int run_converge(const Params& base, const ConvergeOptions& options,
                 const std::string& base_config) {
  const std::vector<Params> members = converge_members(base, options);
  const std::size_t m = members.size();

  // common radii: the coarsest member's interior points (of the composite of its boxes) inside
  // the exterior region
  const mesh::MeshLayout coarse_layout = make_layout(evolution_config(members.front()));
  const Grid coarse = mesh::Composite(coarse_layout).grid();
  std::vector<double> radii;
  for (std::size_t i = coarse.first_interior(); i < coarse.end_interior(); ++i)
    if (coarse.r()[i] >= members.front().norm_rmin && coarse.r()[i] <= *members.front().norm_rmax)
      radii.push_back(coarse.r()[i]);
  if (radii.empty())
    throw ParamError("--norm-rmin", fmt::format("{}", members.front().norm_rmin),
                     "the exterior region holds no grid point of the coarsest member");
  std::vector<Var> fields;
  for (const auto& name : options.fields)
    fields.push_back(*var_from_name(name));

  // what every member samples, exactly: saved samples are reused only for the same key
  std::string samples_key = fmt::format("fields = {}\nradii =", fmt::join(options.fields, ","));
  for (double r : radii)
    samples_key += fmt::format(" {:.17g}", r);

  create_output_dir("--out", options.out);
  std::vector<MemberRecord> records(m);
  std::mutex log_mutex;
  auto member_task = [&](std::size_t k) {
    {
      MemberRecord& rec = records[k];
      const auto start = std::chrono::steady_clock::now();
      {
        const std::lock_guard lock(log_mutex);
        say("gbssn1d converge: member N = {} started\n", members[k].N);
      }
      try {
        const Params& p = members[k];
        create_output_dir("--out", p.out);
        Simulation sim(evolution_config(p));
        sim.on_series = [&](Simulation& s) {
          const std::vector<DerivedProfiles> levels_d = s.level_profiles();
          rec.rows.push_back(s.series_row(s.composite_profiles(levels_d)));
          std::vector<double> samples;
          for (Var v : fields)
            for (double r : radii)
              samples.push_back(s.at_radius(v, r));
          rec.field_samples.push_back(std::move(samples));
          std::vector<double> H_samples;
          for (double r : radii)
            H_samples.push_back(s.H_at_radius(levels_d, r));
          rec.H_samples.push_back(std::move(H_samples));
        };
        const std::string config = config_text(p); // the member's own configuration
        sim.checkpoint_config = config;
        sim.label = fmt::format(" converge N={}", p.N);
        const fs::path samples_file = fs::path(p.out) / "converge_samples.bin";
        sim.on_checkpoint = [&](const Checkpoint& c) {
          write_samples(samples_file, samples_key, c.step, rec);
        };
        // A member with a checkpoint of this configuration, and its samples, continues from it.
        std::optional<Checkpoint> from;
        if (fs::is_regular_file(fs::path(p.out) / "checkpoint.bin")) {
          try {
            Checkpoint c = read_checkpoint(fs::path(p.out) / "checkpoint.bin");
            if (config_differences(c.config, config, {"tmax", "out", "force"}).empty()
                && c.t <= p.tmax)
              if (auto saved = read_samples(samples_file, samples_key, c.step)) {
                Output::check_resumable(p.out, c.marks);
                sim.restore(c);
                rec = std::move(*saved);
                from = std::move(c);
              }
          } catch (const CheckpointError&) { // not resumable: the member starts afresh
          } catch (const OutputError&) {
          }
        }
        std::optional<Output> out_storage;
        if (from) {
          const std::lock_guard lock(log_mutex);
          say("gbssn1d converge: member N = {} resumes at t = {}\n", p.N, from->t);
          out_storage.emplace(p.out, config + sim.run_facts(), from->marks);
        } else {
          out_storage.emplace(p.out, config + sim.run_facts());
        }
        Output& out = *out_storage;
        try {
          sim.run(&out);
          out.write_end(fmt::format("completed at t = {}", sim.time()));
          const std::lock_guard lock(log_mutex);
          say("gbssn1d converge: member N = {} completed at t = {} ({:.1f} s)\n", p.N, sim.time(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        } catch (const OutputError&) {
          throw;
        } catch (const std::exception& e) { // stopped or interrupted: say so in the file too
          out.write_end(fmt::format("stopped: {}", e.what()));
          throw;
        }
      } catch (const std::exception& e) {
        rec.error = e.what();
        const std::lock_guard lock(log_mutex);
        say("gbssn1d converge: member N = {} failed: {}\n", members[k].N, e.what());
      }
    }
  };
  install_stop_handlers(); // members stop between steps; the partial files stay
  run_tasks(m, options.jobs, member_task);

  // times common to all members
  std::size_t n_times = records.front().rows.size();
  for (const auto& rec : records)
    n_times = std::min(n_times, rec.rows.size());
  const auto Nd = [&](std::size_t k) { return static_cast<double>(members[k].N); };

  write_file_atomically(fs::path(options.out) / "config.toml",
                        header_text("")
                            + fmt::format("# converge: N = {}, fields {}\n",
                                          fmt::join(options.N, ","), fmt::join(options.fields, ","))
                            + base_config);

  // How the study ended, in both files' headers and as their last line: a reader (and a plot
  // script) must be able to tell a partial study from a complete one.
  const int signal = stop_signal();
  std::string failed;
  for (std::size_t k = 0; k < m; ++k)
    if (!records[k].error.empty() && failed.empty())
      failed = fmt::format("member N = {} failed: {}", members[k].N, records[k].error);
  const double t_common = n_times > 0 ? records.front().rows[n_times - 1].t : 0.0;
  const std::string ending =
      signal != 0 ? fmt::format("interrupted by {} at t = {} (partial: every member only to this "
                                "time; rerun the same command to resume)",
                                signal_name(signal), t_common)
      : !failed.empty()
          ? fmt::format("stopped: {} (partial: common times up to t = {})", failed, t_common)
          : fmt::format("completed at t = {}", t_common);
  const std::string status_line = fmt::format("status: {}\n", ending);
  const std::string end_line = fmt::format("# end: {}\n", ending);

  // convergence.dat
  std::vector<std::string> cols{"t"};
  // the norms compared across members: column stem, order stem, value
  // (judged: part of the verdict; scale: the quantity's size, 1/M^2 for H and M_r, 1/M for
  // G^r, of which kRoundOffFloor is round-off)
  struct Norm {
    const char *column, *order;
    double SeriesRow::*value;
    bool judged;
    int length_power;
  };
  const Norm norms[] = {{"H_L2_ext", "H", &SeriesRow::H_L2_ext, true, -2},
                        {"M_L2_ext", "M", &SeriesRow::M_L2_ext, true, -2},
                        {"G_L2_ext", "G", &SeriesRow::G_L2_ext, true, -1},
                        {"H_L2_R", "H_R", &SeriesRow::H_L2_R, true, -2},
                        {"M_L2_R", "M_R", &SeriesRow::M_L2_R, true, -2},
                        {"H_L2_int", "H_int", &SeriesRow::H_L2_int, false, -2}};
  constexpr int n_norms = static_cast<int>(std::size(norms));
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

  // The verdict (study/verdict.hpp): every judged norm at each pair of neighbouring members and
  // every field's differences at each triple, over the common times.
  std::vector<OrderSeries> series;
  for (const auto& c : norms) {
    if (!c.judged)
      continue;
    for (std::size_t k = 0; k + 1 < m; ++k) {
      OrderSeries s{c.column, {Nd(k), Nd(k + 1)}, {}, {}, {}};
      for (std::size_t q = 0; q < n_times; ++q) {
        s.coarse.push_back(records[k].rows[q].*c.value);
        s.fine.push_back(records[k + 1].rows[q].*c.value);
        s.floor.push_back(kRoundOffFloor * std::pow(base.M, c.length_power));
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
        // the field's scale: the RMS of its coarsest member's values at the radii; at t = 0
        // the members start from the same data and differ by the 6th-order interpolation
        // onto the coarsest radii alone, which the three-level formula does not describe: not
        // judged
        s.floor.push_back(records.front().rows[q].t == 0.0
                              ? std::numeric_limits<double>::infinity()
                              : kRoundOffFloor * rms_difference(a, zeros, off, radii.size()));
      }
      series.push_back(std::move(s));
    }
  const Verdict verdict =
      judge_convergence(series, options.expect_order.value_or(static_cast<double>(base.fd_order)));
  const auto time_at = [&](std::size_t q) { return time_text(records.front().rows[q].t); };
  const OrderJudgement* failure = verdict.failure();
  std::string judged; // the rule's finding over the common times
  // where one item's orders fall below the threshold: the first time, the lowest order
  const auto dips = [&](const OrderJudgement& j) {
    return j.below == 0
               ? fmt::format("lowest order {} at t = {}", order_text(j.worst), time_at(j.worst_at))
               : fmt::format("order {} at t = {} is the first below {}, lowest {} at "
                             "t = {}",
                             order_text(j.first_order), time_at(j.first_below),
                             order_text(verdict.threshold), order_text(j.worst),
                             time_at(j.worst_at));
  };
  const auto rms_text = [&](const OrderJudgement& j) {
    std::string text = fmt::format("order of its RMS over time {}", order_text(j.p_rms));
    if (j.windows_below > 0)
      text +=
          fmt::format(", over t = {} ... {} {} ({} of {} windows of the run below {})",
                      time_at(j.window_begin), time_at(j.window_end), order_text(j.window_order),
                      j.windows_below, j.windows, order_text(verdict.threshold));
    return text;
  };
  if (failure) {
    std::size_t more = 0;
    for (const auto& i : verdict.items)
      more += i.converges ? 0 : 1;
    judged = fmt::format("does not converge: {} at {}: {}; {} (expected order {}){}",
                         failure->quantity, resolutions_text(failure->N), dips(*failure),
                         rms_text(*failure), verdict.design,
                         more > 1 ? fmt::format(" (and {} more quantity/resolution sets; see the "
                                                "order lines)",
                                                more - 1)
                                  : std::string());
  } else if (const OrderJudgement* w = verdict.weakest()) {
    judged = fmt::format("converges: every monitored order of an RMS over time (norms: also over "
                         "each tenth of the run) at least {} (expected order {}); the lowest over "
                         "time is {} ({} at {})",
                         order_text(verdict.threshold), verdict.design, order_text(w->p_rms),
                         w->quantity, resolutions_text(w->N));
  } else {
    judged = "converges at round-off: no monitored difference is above the round-off floor";
  }
  const std::string verdict_text =
      signal != 0       ? "not judged: the study was interrupted"
      : !failed.empty() ? fmt::format("does not converge: {} (over the common times up to t = "
                                      "{}: {})",
                                      failed, t_common, judged)
                        : judged;
  std::string order_lines = fmt::format(
      "verdict: {}\nverdict rule: for each norm at each pair of neighbouring members, and each "
      "field's differences at each triple, at the times where the coarse value is above "
      "{:g} of its scale (1/M^2 for H and M_r, 1/M for G^r, the field's RMS for fields), the "
      "order of the RMS over those times (for norms also of the RMS over each tenth of them) "
      "must be at least {} (expected order {} - {}); H_L2_int (inside the horizon) is not judged, "
      "nor are "
      "field differences at t = 0 (the same data, interpolated)\n",
      verdict_text, kRoundOffFloor, order_text(verdict.threshold), verdict.design, kOrderTolerance);
  for (const auto& j : verdict.items)
    order_lines += fmt::format("order {} {}: {}; {} of {} judged times below {}{}: {}\n",
                               j.quantity, resolutions_text(j.N), rms_text(j), j.below, j.judged,
                               order_text(verdict.threshold), j.judged > 0 ? ", " + dips(j) : "",
                               j.converges ? "converges" : "does not converge");
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
    for (double tw : times) {
      if (n_times == 0)
        break;
      std::size_t s = 0;
      for (std::size_t q = 0; q < n_times; ++q)
        if (std::abs(records.front().rows[q].t - tw) < std::abs(records.front().rows[s].t - tw))
          s = q;
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
  if (signal != 0) {
    say("gbssn1d converge: N = {} {}; the partial norms and orders are in {}/convergence.dat\n",
        fmt::join(options.N, ", "), ending, options.out);
    return 128 + signal;
  }
  if (!failed.empty()) {
    say("gbssn1d converge: N = {} {}; does not converge; see {}/convergence.dat\n",
        fmt::join(options.N, ", "), ending, options.out);
    return 3;
  }
  if (failure) {
    say("gbssn1d converge: N = {} completed at t = {}, but {}; norms, orders and the verdict in "
        "{}/convergence.dat\n",
        fmt::join(options.N, ", "), t_common, judged, options.out);
    return 4;
  }
  say("gbssn1d converge: N = {} completed at t = {}; {}; norms, orders and the verdict in "
      "{}/convergence.dat\n",
      fmt::join(options.N, ", "), t_common, judged, options.out);
  return 0;
}

} // namespace gbssn1d
