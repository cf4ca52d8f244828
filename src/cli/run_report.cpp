#include "cli/run_report.hpp"

#include "core/console.hpp"
#include "core/stop_signal.hpp"
#include "evolution/observe.hpp"

#include <fmt/format.h>

#include <chrono>
#include <string>

namespace gbssn1d {

int run_and_report(Simulation& sim, Output& out, const Params& p) {
  install_stop_handlers();
  const auto start = std::chrono::steady_clock::now();
  // How the run ended goes to stderr and, as the last line, into timeseries.dat.
  auto stopped = [&](const std::string& prefix, const std::string& what, const std::string& kept,
                     int status) {
    say("gbssn1d: {}{}; {}\n", prefix, what, kept);
    out.write_end(fmt::format("stopped: {}", what));
    return status;
  };
  try {
    sim.run(&out);
  } catch (const NonFiniteError& e) {
    return stopped("error: ", e.what(), "output up to the last finite state kept in " + p.out, 3);
  } catch (const HorizonFinderError& e) {
    return stopped("error: ", e.what(), "output up to then kept in " + p.out, 3);
  } catch (const Interrupted& e) {
    return stopped("", e.what(),
                   fmt::format("output up to then and a checkpoint kept in {}; resume with: {}",
                               p.out, resume_command(p.out)),
                   128 + e.signal);
  } catch (const OutputError& e) {
    say("gbssn1d: error: {}; the output in {} is incomplete\n", e.what(), p.out);
    try {
      out.write_end(fmt::format("stopped: {}", e.what())); // other files may still take it
    } catch (const OutputError&) {
    }
    return 1;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.write_end(fmt::format("completed at t = {}", sim.time()));
  say("gbssn1d: reached t = {} in {:.2f} s ({} steps, {} RHS evaluations)\n", sim.time(), wall,
      sim.schedule().n_steps, sim.evaluations());
  return 0;
}

} // namespace gbssn1d
