// SIGTERM and SIGINT as a request to stop: the handler only records the signal; evolutions
// poll it between steps (finish the step, write what is due, record how the run ended), and
// sweeps pass it on to their members.
#pragma once

#include <string>

namespace gbssn1d {

/// Installs the handlers for SIGTERM and SIGINT (idempotent).
void install_stop_handlers();
/// The signal received since the handlers were installed, or 0.
int stop_signal();
/// "SIGTERM", "SIGINT", or "signal <n>".
std::string signal_name(int signal);

} // namespace gbssn1d
