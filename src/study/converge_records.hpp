// What a converge member records at every series output (its series row, the fields and H at
// the study's common radii), saved beside each of its checkpoints so that a rerun continues it.
#pragma once

#include "io/output.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gbssn1d {

/// What one member records at every series output.
struct MemberRecord {
  std::vector<SeriesRow> rows;
  std::vector<std::vector<double>> field_samples; ///< per output: fields x common radii
  std::vector<std::vector<double>> H_samples;     ///< per output: H at the common radii
  std::string error;                              ///< non-empty if the member failed
  bool write_failed = false; ///< the failure was a write (full disk, file-size limit)
};

/// A member's samples saved with each of its checkpoints (DIR/N<n>/converge_samples.bin), so
/// that a rerun of the study continues the member from the checkpoint: what was sampled (`key`:
/// the fields and the radii, which depend on the study's coarsest member), the step they belong
/// to, then the rows and the samples, each list as a count and raw doubles, then the FNV-1a
/// 64-bit hash of every byte before it. Samples of another key, or whose hash does not match
/// (a flipped or cut byte), are never reused.
void write_samples(const std::filesystem::path& file, const std::string& key, std::int64_t step,
                   const MemberRecord& rec);
/// The samples saved with the checkpoint at `step`, or nothing (missing, other step, checksum
/// wrong, broken), with the reason in `why` when given (samples_other_step: all but the step
/// agree).
inline constexpr const char* samples_other_step = "it belongs to another step";
std::optional<MemberRecord> read_samples(const std::filesystem::path& file, const std::string& key,
                                         std::int64_t step, std::string* why = nullptr);

/// What a member that completed keeps of its run (DIR/N<n>/converge_completed.bin), so that a
/// rerun of the study (an interrupted one's) takes its records from there instead of running it
/// again: the samples, as write_samples writes them, under the key `key` (the samples' and the
/// member's configuration, completed_key), with the hash of the output files it completed with
/// (output_files_hash) in place of a step. Reused only while the key and those files are the
/// same: a member folder written since by another command (evolve --force) runs again.
inline constexpr const char* completed_file_name = "converge_completed.bin";
std::string completed_key(const std::string& samples_key, const std::string& member_config);
/// The FNV-1a hash of the member's timeseries.dat, profiles.dat and horizon.dat (each as a
/// length and its bytes; an absent file as none), as a step field holds it.
std::int64_t output_files_hash(const std::filesystem::path& dir);
/// The RMS of a - b over [offset, offset + count).
double rms_difference(const std::vector<double>& a, const std::vector<double>& b,
                      std::size_t offset, std::size_t count);

} // namespace gbssn1d
