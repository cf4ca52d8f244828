// One member of a convergence study (gbssn1d converge): evolved into its folder, recording the
// samples the study compares, continued from its own checkpoint, or, when it completed with
// the same inputs and its output files are as it left them, taken from what it kept.
#pragma once

#include "study/converge_report.hpp"

#include <cstddef>
#include <mutex>
#include <optional>
#include <string>

namespace gbssn1d {

/// Member k run (or continued) into its folder, recording into study.records[k]; a failure is
/// recorded there, not thrown. `hAH` is the content of --rah-hAH-file as the study read it
/// (nothing when not in use): the member keeps a copy in its folder, as evolve does, and runs
/// from it, and its checkpoints record the copy's hash (`gbssn1d resume` checks it). Messages
/// go to stderr under `log_mutex`.
void run_converge_member(ConvergeStudy& study, std::size_t k, const std::optional<std::string>& hAH,
                         std::mutex& log_mutex);

} // namespace gbssn1d
