// Which time interpolation fills a fine level's outer ghosts (and buffer) from the coarser
// level: the choice alone, for configurations; the weights are in mesh/time_interpolation.hpp.
#pragma once

namespace gbssn1d::mesh {

enum class TimeInterpolation {
  /// Every RK4 stage of a fine step gets ghosts consistent with that stage: the stage values
  /// of the fine step, Taylor-expanded about the fine step's start, with the Taylor
  /// coefficients from the coarse step's stages (McCorquodale & Colella 2011, CAMCoS 6:1,
  /// Sec. 3; Mongwane 2015, GRG 47:60). Local error O(dt^4) in every stage: 4th order.
  rk_stages,
  /// Every stage gets the coarse step's RK4 dense output (the cubic continuous extension) at
  /// the stage's time: accurate values, but not what the RK4 stages hold (the stages are
  /// only 1st/2nd-order approximations of the solution at their times), so the boundary is
  /// inconsistent with the interior stages.
  dense_output,
  /// Ghosts and a buffer of buffer_cells are filled once per fine step (not per stage) by
  /// quadratic Lagrange interpolation in time through the coarse level's last three time
  /// levels (linear while only two exist), the default of Carpet and BAM (Schnetter, Hawley &
  /// Hawke 2004, CQG 21:1465; Bruegmann et al. 2008, PRD 77:024027): 2nd/3rd order in time.
  quadratic,
};

} // namespace gbssn1d::mesh
