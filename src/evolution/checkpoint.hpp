// Checkpoints: everything a run needs to continue bit for bit from a step boundary (the state,
// the step, the horizon shift's held h_AH, which is also the finder's seed, the output cadence
// counters and where each output file stood), written atomically into the output directory.
#pragma once

#include "evolution/evolution_config.hpp"
#include "io/output.hpp"
#include "mesh/layout.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gbssn1d {

/// The FNV-1a 64-bit hash of bytes: the checksum of checkpoint.bin and of a converge member's
/// converge_samples.bin.
std::uint64_t fnv1a(std::string_view bytes);

/// A state as a checkpoint file holds it: its values, variable-major as in State. The file
/// records no formulation: the run that resumes gives them its own (Simulation::restore), after
/// resumable_checkpoint has checked their count against its states.
using StateValues = std::vector<double>;

struct Checkpoint {
  /// A stored coarse time level of the stepper (mesh::MeshStepper::TimeLevel), as values.
  struct TimeLevel {
    double t;
    StateValues u;
  };
  std::string config;    ///< the run's configuration (config.toml text)
  std::int64_t step = 0; ///< steps taken; t = step dt
  double t = 0.0, dt = 0.0;
  std::int64_t k_series = 1, k_profiles = 1; ///< the next output times are k dt_series, ...
  std::optional<double> h_AH; ///< held h_AH (the finder's seed) before the next RHS call
  bool had_horizon = false, reported = false;
  std::uint64_t evaluations = 0; ///< RHS evaluations so far
  OutputMarks marks;
  StateValues u; ///< level 0's state (the single grid's)
  // Box-in-box levels (empty for a single grid), format 3:
  std::vector<StateValues> finer;                ///< the states of levels 1 ... L-1
  std::vector<std::optional<double>> level_h_AH; ///< h_AH held by each level's RHS, 0 ... L-1
  std::optional<double> shared_h_AH;             ///< the horizon radius all levels share
  /// boxes: the radii found at the last hierarchy steps, (t, h_AH), oldest first
  std::vector<std::array<double, 2>> h_AH_history;
  /// each level's stored time levels (quadratic time interpolation), 0 ... L-1
  std::vector<std::vector<TimeLevel>> history;
};

/// A checkpoint file that cannot be read, or belongs to another run.
class CheckpointError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Writes `c` to `file` atomically: a temporary file, flushed to disk, then renamed over it.
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c);
/// Throws CheckpointError if the file is missing, truncated or not a checkpoint.
Checkpoint read_checkpoint(const std::filesystem::path& file);

/// The run a checkpoint is to continue: its configuration, levels, each level's state size,
/// step, number of steps and RHS evaluations before the first step (level 0).
struct ResumeTarget {
  const EvolutionConfig& config;
  const mesh::MeshLayout& layout;
  const std::vector<std::size_t>& state_sizes;
  double dt;
  long n_steps;
  std::uint64_t initial_evaluations;
};
/// `c` in this version's layout (states of the legacy layout, 3 ghosts a side, widened), after
/// checking that it belongs to `run`: levels, state sizes, time levels, horizon radii, step,
/// time, output counters and RHS count, each as the uninterrupted run holds it at that step.
/// Throws CheckpointError naming the first mismatch.
Checkpoint resumable_checkpoint(const Checkpoint& c, const ResumeTarget& run);

} // namespace gbssn1d
