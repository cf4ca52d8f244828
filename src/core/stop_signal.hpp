// Signals as a request to stop: the handler only records the signal; evolutions poll it between
// steps (finish the step, write what is due and a checkpoint, record how the run ended), and
// sweeps pass it on to their members. SIGTERM and SIGINT (kill, Ctrl-C), SIGHUP (the terminal
// closed), SIGUSR1 and SIGUSR2 (what batch schedulers send ahead of a time limit, e.g. Slurm's
// --signal) all stop a run resumably.
#pragma once

#include <csignal>
#include <string>

namespace gbssn1d {

inline constexpr int stop_signals[] = {SIGTERM, SIGINT, SIGHUP, SIGUSR1, SIGUSR2};

/// Installs the handlers for the stop signals (idempotent).
void install_stop_handlers();
/// The signal received since the handlers were installed, or 0.
int stop_signal();
/// "SIGTERM", "SIGINT", or "signal <n>".
std::string signal_name(int signal);

} // namespace gbssn1d
