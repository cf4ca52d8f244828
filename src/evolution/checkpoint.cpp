#include "evolution/checkpoint.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>

namespace gbssn1d {

std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

namespace {

// Format 4: the magic line (with the format's number), the fields below in order (native byte
// order, as the file never leaves the machine type that wrote it), then the FNV-1a 64-bit hash
// of every byte before it. Format 3 is format 4 without the output files' body hashes after
// their marks (a resume then checks their lengths alone); format 2 is format 3 without the box
// levels after level 0's state (it is read as a single grid's); format 1 had no hash and is
// refused by name.
constexpr std::string_view magic = "gbssn1d checkpoint 4\n";
constexpr std::string_view magic_3 = "gbssn1d checkpoint 3\n";
constexpr std::string_view magic_2 = "gbssn1d checkpoint 2\n";
constexpr std::string_view magic_prefix = "gbssn1d checkpoint ";
/// The largest checkpoint read (16 GiB: a grid of 2e8 points); anything larger is not one.
constexpr std::uintmax_t max_file_bytes = std::uintmax_t{1} << 34;

/// Reads fields from the checked bytes; never past their end.
class Reader {
public:
  Reader(std::string_view bytes, const std::filesystem::path& path) : rest_(bytes), path_(path) {}
  template <class T>
  T get() {
    T v{};
    get_bytes(&v, sizeof(T));
    return v;
  }
  void get_bytes(void* p, std::size_t n) {
    if (n > rest_.size())
      throw CheckpointError(
          fmt::format("{} is corrupt (a field runs past its end)", path_.string()));
    if (n == 0)
      return; // an empty vector's data() may be null, which memcpy must not be given
    std::memcpy(p, rest_.data(), n);
    rest_.remove_prefix(n);
  }
  std::size_t left() const { return rest_.size(); }

private:
  std::string_view rest_;
  const std::filesystem::path& path_;
};

} // namespace

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c) {
  std::string bytes(magic);
  auto put_bytes = [&](const void* p, std::size_t n) {
    bytes.append(static_cast<const char*>(p), n);
  };
  auto put = [&](const auto& v) { put_bytes(&v, sizeof(v)); };
  put(std::uint64_t{c.config.size()});
  put_bytes(c.config.data(), c.config.size());
  put(c.step);
  put(c.t);
  put(c.dt);
  put(c.k_series);
  put(c.k_profiles);
  put(std::uint8_t{c.h_AH.has_value()});
  put(c.h_AH.value_or(0.0));
  put(std::uint8_t{c.had_horizon});
  put(std::uint8_t{c.reported});
  put(c.evaluations);
  for (std::uint64_t v : {c.marks.series, c.marks.profiles, c.marks.horizons, c.marks.series_header,
                          c.marks.profiles_header, c.marks.horizons_header, c.marks.series_hash,
                          c.marks.profiles_hash, c.marks.horizons_hash})
    put(v);
  auto put_state = [&](const StateValues& u) {
    put(std::uint64_t{u.size()});
    put_bytes(u.data(), u.size() * sizeof(double));
  };
  auto put_optional = [&](const std::optional<double>& v) {
    put(std::uint8_t{v.has_value()});
    put(v.value_or(0.0));
  };
  put_state(c.u);
  put(std::uint64_t{c.finer.size()});
  for (const StateValues& u : c.finer)
    put_state(u);
  put(std::uint64_t{c.level_h_AH.size()});
  for (const auto& h : c.level_h_AH)
    put_optional(h);
  put_optional(c.shared_h_AH);
  put(std::uint64_t{c.h_AH_history.size()});
  for (const auto& th : c.h_AH_history)
    put(th);
  put(std::uint64_t{c.history.size()});
  for (const auto& levels : c.history) {
    put(std::uint64_t{levels.size()});
    for (const auto& [t, u] : levels) {
      put(t);
      put_state(u);
    }
  }
  put(fnv1a(bytes));

  write_file_atomically(file, bytes); // the old checkpoint or the new one, never a mixture
}

namespace {

/// The bytes of a checkpoint file whose magic line and checksum are right (the checksum
/// removed), and its format (2, 3 or 4); CheckpointError otherwise.
std::pair<std::string, int> checked_bytes(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw CheckpointError(fmt::format("{} is not a regular file", file.string()));
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec || size > max_file_bytes)
    throw CheckpointError(fmt::format("{} is not a gbssn1d checkpoint (size)", file.string()));
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    if (!in)
      throw CheckpointError(fmt::format("cannot read {}: {}", file.string(), std::strerror(errno)));
    bytes.resize(size);
    if (!in.read(bytes.data(), static_cast<std::streamsize>(size)))
      throw CheckpointError(fmt::format("cannot read {}", file.string()));
  }
  const std::string_view all(bytes);
  const int format = all.substr(0, magic.size()) == magic       ? 4
                     : all.substr(0, magic_3.size()) == magic_3 ? 3
                     : all.substr(0, magic_2.size()) == magic_2 ? 2
                                                                : 0;
  if (format == 0) {
    if (all.substr(0, magic_prefix.size()) == magic_prefix)
      throw CheckpointError(fmt::format("{} was written in another checkpoint format ({}); this "
                                        "version reads formats 2, 3 and 4",
                                        file.string(),
                                        all.substr(0, all.find('\n')).substr(magic_prefix.size())));
    throw CheckpointError(fmt::format("{} is not a gbssn1d checkpoint", file.string()));
  }
  if (all.size() < magic.size() + sizeof(std::uint64_t))
    throw CheckpointError(fmt::format("{} is truncated", file.string()));
  std::uint64_t stored_hash = 0;
  std::memcpy(&stored_hash, all.data() + all.size() - sizeof(stored_hash), sizeof(stored_hash));
  const std::string_view body = all.substr(0, all.size() - sizeof(stored_hash));
  if (fnv1a(body) != stored_hash)
    throw CheckpointError(fmt::format(
        "{} is corrupt: its checksum does not match (truncated, or changed since written)",
        file.string()));
  bytes.resize(body.size());
  return {std::move(bytes), format};
}

} // namespace

Checkpoint read_checkpoint(const std::filesystem::path& file) {
  const auto [bytes, format] = checked_bytes(file);
  const std::string_view body(bytes);

  Reader r(body.substr(magic.size()), file); // the magic lines have the same length
  Checkpoint c;
  const auto n_config = r.get<std::uint64_t>();
  if (n_config > r.left())
    throw CheckpointError(fmt::format("{} is corrupt", file.string()));
  c.config.resize(n_config);
  r.get_bytes(c.config.data(), n_config);
  c.step = r.get<std::int64_t>();
  c.t = r.get<double>();
  c.dt = r.get<double>();
  c.k_series = r.get<std::int64_t>();
  c.k_profiles = r.get<std::int64_t>();
  const auto flag = [&](const char* what) {
    const auto v = r.get<std::uint8_t>();
    if (v > 1)
      throw CheckpointError(fmt::format("{} is corrupt ({})", file.string(), what));
    return v == 1;
  };
  const bool has_h = flag("h_AH flag");
  const double h = r.get<double>();
  if (has_h)
    c.h_AH = h;
  c.had_horizon = flag("horizon flag");
  c.reported = flag("report flag");
  c.evaluations = r.get<std::uint64_t>();
  for (std::uint64_t* v :
       {&c.marks.series, &c.marks.profiles, &c.marks.horizons, &c.marks.series_header,
        &c.marks.profiles_header, &c.marks.horizons_header})
    *v = r.get<std::uint64_t>();
  c.marks.hashed = format >= 4;
  if (c.marks.hashed)
    for (std::uint64_t* v : {&c.marks.series_hash, &c.marks.profiles_hash, &c.marks.horizons_hash})
      *v = r.get<std::uint64_t>();
  auto get_state = [&](StateValues& u) {
    const auto n = r.get<std::uint64_t>();
    if (n > r.left() / sizeof(double))
      throw CheckpointError(fmt::format("{} is corrupt (its value count)", file.string()));
    u.resize(n);
    r.get_bytes(u.data(), n * sizeof(double));
  };
  auto get_count = [&](std::size_t least_bytes_each) {
    const auto n = r.get<std::uint64_t>();
    if (n > r.left() / least_bytes_each)
      throw CheckpointError(fmt::format("{} is corrupt (a count)", file.string()));
    return static_cast<std::size_t>(n);
  };
  auto get_optional = [&](const char* what) {
    const bool has = flag(what);
    const double v = r.get<double>();
    return has ? std::optional<double>(v) : std::nullopt;
  };
  get_state(c.u);
  if (format >= 3) {
    c.finer.resize(get_count(sizeof(std::uint64_t)));
    for (StateValues& u : c.finer)
      get_state(u);
    c.level_h_AH.resize(get_count(9));
    for (auto& h : c.level_h_AH)
      h = get_optional("level h_AH flag");
    c.shared_h_AH = get_optional("shared h_AH flag");
    c.h_AH_history.resize(get_count(2 * sizeof(double)));
    for (auto& th : c.h_AH_history)
      th = r.get<std::array<double, 2>>();
    c.history.resize(get_count(sizeof(std::uint64_t)));
    for (auto& levels : c.history) {
      levels.resize(get_count(2 * sizeof(std::uint64_t)));
      for (auto& level : levels) {
        level.t = r.get<double>();
        get_state(level.u);
      }
    }
  }
  if (r.left() != 0)
    throw CheckpointError(fmt::format("{} is corrupt (bytes after its last field)", file.string()));
  return c;
}

namespace {

/// Ghosts per side before the finite-difference order became a choice (checkpoint formats 2
/// and 3 of earlier versions).
constexpr std::size_t legacy_ghosts = 3;

/// `u` re-laid out from legacy_ghosts to Grid::n_ghost ghosts per side, if it has the legacy
/// size for `grid`: the interior and the old outer ghosts are kept, the origin ghosts refilled
/// by parity, the new outermost ghosts copied from the last old one. At 4th order nothing reads
/// them but their own boundary condition, so the run continues as it would have.
void widen_legacy_ghosts(StateValues& u, const Grid& grid) {
  const std::size_t n = grid.n_interior(), old_total = n + 2 * legacy_ghosts;
  constexpr std::size_t n_fields = n_evolved(Formulation::bssn); // legacy files are BSSN's
  if (u.size() != n_fields * old_total || grid.n_total() == old_total)
    return;
  State w(Formulation::bssn, grid.n_total());
  for (std::size_t v = 0; v < n_fields; ++v) {
    const double* from = u.data() + v * old_total;
    double* to = w.data() + v * grid.n_total();
    for (std::size_t k = 0; k < n + legacy_ghosts; ++k) // interior and the old outer ghosts
      to[grid.first_interior() + k] = from[legacy_ghosts + k];
    for (std::size_t k = n + legacy_ghosts; k < n + Grid::n_ghost; ++k)
      to[grid.first_interior() + k] = from[legacy_ghosts + n + legacy_ghosts - 1];
  }
  fill_origin_ghosts(w, grid);
  u = w.values();
}

} // namespace

Checkpoint resumable_checkpoint(const Checkpoint& checkpoint, const ResumeTarget& run) {
  const std::size_t n_levels = run.layout.levels();
  Checkpoint c = checkpoint;
  if (c.finer.size() + 1 == n_levels) {
    widen_legacy_ghosts(c.u, run.layout.grid(0));
    for (std::size_t l = 1; l < n_levels; ++l)
      widen_legacy_ghosts(c.finer[l - 1], run.layout.grid(l));
    for (std::size_t l = 0; l < c.history.size() && l < n_levels; ++l)
      for (auto& h : c.history[l])
        widen_legacy_ghosts(h.u, run.layout.grid(l));
  }
  if (c.finer.size() + 1 != n_levels)
    throw CheckpointError(
        fmt::format("the checkpoint has {} levels, this grid {}", c.finer.size() + 1, n_levels));
  for (std::size_t l = 0; l < n_levels; ++l) {
    const StateValues& u = l == 0 ? c.u : c.finer[l - 1];
    if (u.size() != run.state_sizes[l])
      throw CheckpointError(fmt::format("the checkpoint has {} values{}, this grid {}", u.size(),
                                        n_levels > 1 ? fmt::format(" on level {}", l) : "",
                                        run.state_sizes[l]));
  }
  if (n_levels > 1) {
    if (c.level_h_AH.size() != n_levels || c.history.size() != n_levels)
      throw CheckpointError("the checkpoint's levels are incomplete");
    for (std::size_t l = 0; l < n_levels; ++l) {
      // quadratic interpolation keeps two earlier time levels of every level but the finest
      const std::size_t expected =
          run.config.stepping.time == mesh::TimeInterpolation::quadratic && l + 1 < n_levels ? 2
                                                                                             : 0;
      if (c.history[l].size() != expected)
        throw CheckpointError(fmt::format("the checkpoint holds {} time levels of level {}, this "
                                          "run keeps {}",
                                          c.history[l].size(), l, expected));
      for (const auto& h : c.history[l])
        if (h.u.size() != run.state_sizes[l] || !(h.t < c.t))
          throw CheckpointError(fmt::format(
              "the checkpoint's time level t = {} of level {} is not this run's", h.t, l));
      if (c.level_h_AH[l] && !(std::isfinite(*c.level_h_AH[l]) && *c.level_h_AH[l] > 0.0))
        throw CheckpointError(fmt::format("the checkpoint's horizon radius {} of level {} is "
                                          "not a radius",
                                          *c.level_h_AH[l], l));
    }
  }
  if (c.dt != run.dt)
    throw CheckpointError(
        fmt::format("the checkpoint's step {} is not this run's {}", c.dt, run.dt));
  if (c.step < 0 || c.step > run.n_steps)
    throw CheckpointError(fmt::format(
        "the checkpoint at step {} lies outside this run's steps 0 ... {} (--tmax = {})", c.step,
        run.n_steps, run.config.tmax));
  // Every counter must be the one the run itself would hold at this step (run() sets
  // t = n dt, writes the outputs at k dt_series <= t, and evaluates the RHS four times a step).
  if (c.t != static_cast<double>(c.step) * run.dt)
    throw CheckpointError(fmt::format("the checkpoint's time {} is not step {} x dt = {}", c.t,
                                      c.step, static_cast<double>(c.step) * run.dt));
  const double tol = 1e-9 * run.dt;
  auto next_output = [&](double cadence) { // the first k with k cadence > t (as run() counts)
    auto k = static_cast<std::int64_t>(std::floor((c.t + tol) / cadence)) + 1;
    if (k > 1 && static_cast<double>(k - 1) * cadence > c.t + tol)
      --k;
    if (static_cast<double>(k) * cadence <= c.t + tol)
      ++k;
    return k;
  };
  if (c.k_series != next_output(run.config.dt_series)
      || c.k_profiles != next_output(run.config.dt_profiles))
    throw CheckpointError(fmt::format(
        "the checkpoint's output counters ({}, {}) are not those of t = {} ({}, {})", c.k_series,
        c.k_profiles, c.t, next_output(run.config.dt_series), next_output(run.config.dt_profiles)));
  if (c.evaluations != run.initial_evaluations + 4 * static_cast<std::uint64_t>(c.step))
    throw CheckpointError(fmt::format("the checkpoint's RHS count {} is not {} + 4 x step {}",
                                      c.evaluations, run.initial_evaluations, c.step));
  for (const auto& h : {c.h_AH, c.shared_h_AH})
    if (h && !(std::isfinite(*h) && *h > 0.0))
      throw CheckpointError(fmt::format("the checkpoint's horizon radius {} is not a radius", *h));
  return c;
}

} // namespace gbssn1d
