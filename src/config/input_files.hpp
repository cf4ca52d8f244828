// The files a run's flags name (--rah-hAH-file): their content as a run reads it, the copy a
// run keeps of it in its folder, and the line that records the content's hash beside the
// configuration, so that whatever resumes or reuses a run (resume, a converge member, a sweep
// rerun, --member, --collect) tells a file edited since from the one the run read.
#pragma once

#include "config/params.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gbssn1d {

/// A run's copy of --rah-hAH-file, in its folder (evolve's and a converge member's alike).
inline constexpr std::string_view prescribed_horizon_copy = "rah-hAH-file.dat";

/// The line that records the FNV-1a hash of --rah-hAH-file's content, as a run read it: a '#'
/// line (configurations are compared by their keys; config.toml stays readable by --config).
inline constexpr std::string_view copy_hash_key = "# rah-hAH-file.dat fnv1a = ";

/// The bytes of --rah-hAH-file when it is in use (rahA != 0), nothing otherwise; ParamError
/// naming the flag if it cannot be read.
std::optional<std::string> prescribed_horizon_content(const Params& p);

/// The hash of a file's bytes as the record line writes it (16 hex digits).
std::string copy_hash(const std::string& bytes);

/// The record line of `content` ("" for none): copy_hash_key, the hash, a line end.
std::string copy_hash_line(const std::optional<std::string>& content);

/// The record line of the content --rah-hAH-file names now ("" when the file is not in use;
/// "... (unreadable)" for a file that cannot be read: no run reads it, and a rerun that can
/// differs).
std::string input_files_text(const Params& p);

/// The hash a text (a configuration, a checkpoint's configuration, a sweep member's inputs)
/// records of --rah-hAH-file, if it records one.
std::optional<std::string> recorded_copy_hash(const std::string& text);

/// Where two texts record different contents of the files named by flags, as "rah-hAH-file
/// content: fnv1a A -> B" ("(none)" for a text that records none); empty when they agree.
std::vector<std::string> input_file_differences(const std::string& old_text,
                                                const std::string& new_text);

} // namespace gbssn1d
