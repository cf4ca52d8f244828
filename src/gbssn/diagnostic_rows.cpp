// The diagnostics of every interior point (gbssn/rhs.hpp: diagnostic_rows) as one loop per
// finite-difference order and formulation, which vectorises as the right-hand side's point loop
// does (gbssn/rhs_loop.hpp): the data of each point gathered by the same template as
// adm_point_data's, the constraints, areal radius and expansion by the same functions. At
// every output time of a run these were a call per point (about 12% of a 9-box run with a row
// of the time series every 1 M, profile).
#include "gbssn/dispatch.hpp"
#include "gbssn/equations.hpp"
#include "gbssn/rhs.hpp"
#include "gbssn/rhs_loop.hpp"
#include "gbssn/z4c.hpp"

#include <stdexcept>

namespace gbssn1d {

namespace {

/// with_constraints = false: the areal radius and expansion alone (the horizon finder's), whose
/// loop leaves out the derivatives only the constraints take.
template <int p, Formulation formulation, Matter matter, bool with_constraints>
void diagnostic_rows_at(const State& u, const Grid& grid, const DiagnosticRows& out,
                        std::size_t k_begin, std::size_t k_end) {
  const point_loop::Rows rows(u, grid);
  const double inv_dx = 1.0 / grid.dx();
  const double *const r = grid.r().data(), *const inv_r = grid.inv_r().data(),
                      *const inv_rx = grid.inv_dr_dx().data(),
                      *const d2_fx = grid.d2_fx_coeff().data();
  const std::size_t first = grid.first_interior() + k_begin, n = k_end - k_begin;
  // the rows written are the caller's, apart from the state and the grid
#pragma GCC ivdep
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = first + k;
    point_loop::Differences ko; // unused here
    PointData pd = point_loop::gather<p, fd::Upwind::lopsided, Fields(formulation, matter)>(
        rows, i, r[i], inv_r[i], inv_dx, inv_rx[i], d2_fx[i], ko);
    pd = diagnosed<formulation>(pd);
    if constexpr (with_constraints) {
      const Constraints c = constraints<MatterPolicy<matter>>(pd);
      out.H[k] = c.H;
      out.M_r[k] = c.M_r;
      out.G_r[k] = c.G_r;
      out.m_ms[k] = misner_sharp_mass(pd);
      if constexpr (matter != Matter::none)
        out.flux[k] = energy_flux(pd, MatterPolicy<matter>::stress_energy(pd, 1.0 / pd.f[Var::a]));
    }
    out.R_areal[k] = areal_radius(pd);
    out.Theta_plus[k] = expansion_plus(pd);
  }
}

template <int p, Formulation formulation, Matter matter>
void diagnostic_rows_as(const State& u, const Grid& grid, const DiagnosticRows& out,
                        std::size_t k_begin, std::size_t k_end) {
  if (out.H)
    diagnostic_rows_at<p, formulation, matter, true>(u, grid, out, k_begin, k_end);
  else
    diagnostic_rows_at<p, formulation, matter, false>(u, grid, out, k_begin, k_end);
}

} // namespace

void diagnostic_rows(const State& u, const Grid& grid, const DiagnosticRows& out,
                     std::size_t k_begin, std::size_t k_end) {
  if (k_begin > k_end || k_end > grid.n_interior())
    throw std::out_of_range("diagnostic_rows: points outside the interior");
  if (!out.R_areal || !out.Theta_plus
      || (out.H || out.M_r || out.G_r || out.m_ms) != (out.H && out.M_r && out.G_r && out.m_ms))
    throw std::invalid_argument("diagnostic_rows: R_areal and Theta_plus, and all three "
                                "constraints with the Misner-Sharp mass or none of them");
  if ((out.flux != nullptr) != (out.H != nullptr && u.matter() != Matter::none))
    throw std::invalid_argument("diagnostic_rows: the energy flux with the constraints of a "
                                "state with matter, and only then");
  with_order(grid.fd_order(), [&]<int p>() {
    with_formulation(u.formulation(), [&]<Formulation f>() {
      // matter only at the order it is offered with (validate()), so that the other orders
      // compile no matter loop
      if constexpr (p == 4)
        with_matter(u.matter(),
                    [&]<Matter m>() { diagnostic_rows_as<p, f, m>(u, grid, out, k_begin, k_end); });
      else if (u.matter() != Matter::none)
        throw std::logic_error("diagnostics of matter at an --fd-order other than 4 (rejected "
                               "by validate)");
      else
        diagnostic_rows_as<p, f, Matter::none>(u, grid, out, k_begin, k_end);
    });
  });
}

void diagnostic_rows(const State& u, const Grid& grid, const DiagnosticRows& out) {
  diagnostic_rows(u, grid, out, 0, grid.n_interior());
}

} // namespace gbssn1d
