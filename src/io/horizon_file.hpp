// An open-loop h_AH(t) for the horizon-adjusting shift (--rah-hAH-file): the t and r_ah
// columns of a horizon.dat or timeseries.dat, equally spaced in t and covering the run, as a
// cubic B-spline with 4th-order end slopes. Its numbers are read by the checked table reader
// (io/table.hpp); t must be finite and increase from row to row, r_ah be finite and positive.
// A refused file's message names the line and why.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace gbssn1d {

/// Why a file cannot serve as h_AH(t) ("needs the columns 't' and 'r_ah'", "line 7: r_ah = -0.9
/// is not a radius (must be positive)", ...).
class HorizonFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// h_AH(t) from `path` for a run to t_end; throws HorizonFileError.
std::function<double(double)> read_horizon_history(const std::string& path, double t_end);

} // namespace gbssn1d
