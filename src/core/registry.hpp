// The one registry of evolved variables.
//
// Every evolved field is named here once, with its index in the state vector, the name printed
// in output headers, its parity at r = 0 (equations document, Sec. 7) and its asymptotic value,
// wave family and fall-off for the Sommerfeld outer boundary (Sec. 8); the family's speed comes
// from the gauge (Gauge::speed, gbssn/rhs_params.hpp). Ghost zones, point data, boundary
// conditions and output columns are all driven from this table. A formulation evolves the first
// n_evolved(f) rows: BSSN all but Theta, Z4c Theta too (with K-hat = K - 2 Theta in K's row,
// Sec. 17); matter adds its own rows after them (the scalar field's Phi and Pi, Sec. 19). A
// state's rows, and where each lies, are its Fields'.
#pragma once

#include "core/formulation.hpp"
#include "core/wave.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace gbssn1d {

enum class Var : std::size_t { alpha, beta, B, chi, a, b, K, A_a, Delta_r, Theta, Phi, Pi };

/// Every variable any formulation or matter evolves; a state holds its Fields' rows of them.
inline constexpr std::size_t n_vars = 12;

struct VarInfo {
  Var var;
  std::string_view name; ///< column name in output files
  int parity;            ///< +1 even, -1 odd under r -> -r
  double asymptotic;     ///< f_inf, the value at spatial infinity
  Wave wave;             ///< family of the Sommerfeld wave speed v (Gauge::speed)
  double falloff;        ///< n in f - f_inf ~ u(r - v t) / r^n
};

// Sec. 7 (parity) and Sec. 8 (asymptotics). K carries the slicing's gauge mode, so it leaves
// at the slicing's speed, like alpha; beta, B and Delta^r at the shift's.
inline constexpr std::array<VarInfo, n_vars> registry{{
    {Var::alpha, "alpha", +1, 1.0, Wave::slicing, 1.0},
    {Var::beta, "beta", -1, 0.0, Wave::shift, 1.0},
    {Var::B, "B", -1, 0.0, Wave::shift, 1.0},
    {Var::chi, "chi", +1, 1.0, Wave::light, 1.0},
    {Var::a, "a", +1, 1.0, Wave::light, 1.0},
    {Var::b, "b", +1, 1.0, Wave::light, 1.0},
    {Var::K, "K", +1, 0.0, Wave::slicing, 1.0},
    {Var::A_a, "A_a", +1, 0.0, Wave::light, 1.0},
    {Var::Delta_r, "Delta_r", -1, 0.0, Wave::shift, 1.0},
    // Z4c only (Sec. 17): the constraint Theta propagates at the speed of light
    {Var::Theta, "Theta", +1, 0.0, Wave::light, 1.0},
    // the scalar field (Sec. 19): Phi and Pi = n^a d_a Phi, even, leaving at the speed of light
    {Var::Phi, "Phi", +1, 0.0, Wave::light, 1.0},
    {Var::Pi, "Pi", +1, 0.0, Wave::light, 1.0},
}};

constexpr std::size_t index(Var v) {
  return static_cast<std::size_t>(v);
}
constexpr const VarInfo& info(Var v) {
  return registry[index(v)];
}

/// What a formulation declares, so that the rest of the code asks it instead of branching on
/// its name: the registry rows it evolves, how the ADM K is read from them, and the series
/// columns and legend of its own besides every formulation's.
struct FormulationTraits {
  Formulation formulation;
  /// It evolves the registry's first n_fields rows.
  std::size_t n_fields;
  /// The ADM K = (K's row) + adm_K_theta Theta: 0 where K's row is the ADM K (BSSN); 2 where
  /// it is K-hat = K - 2 Theta (Z4c, (Z1)).
  double adm_K_theta;
  /// timeseries.dat's columns of its own, after every formulation's (io/output.cpp).
  std::span<const std::string_view> extra_series;
  /// Their line of the series legend (empty: none).
  std::string_view series_legend;

  constexpr std::span<const VarInfo> rows() const { return {registry.data(), n_fields}; }
  constexpr bool evolves(Var v) const { return index(v) < n_fields; }
  /// K's row holds the ADM K itself.
  constexpr bool K_is_adm() const { return adm_K_theta == 0.0; }
};

inline constexpr std::array<std::string_view, 3> z4c_extra_series{"G_L2_R", "Theta_L2_ext",
                                                                  "Theta_L2_R"};

/// One row per Formulation, in enum order: BSSN (Sec. 2-3), the nine rows before Theta; Z4c
/// (Sec. 17), ten, with K-hat in K's row; BSSN with the Eulerian volume choice (Sec. 18),
/// BSSN's rows.
inline constexpr std::size_t n_bssn_rows = index(Var::Theta);
inline constexpr std::array<FormulationTraits, 3> formulations{{
    {Formulation::bssn, n_bssn_rows, 0.0, {}, ""},
    {Formulation::z4c, n_bssn_rows + 1, 2.0, z4c_extra_series,
     "Z4c: K is the ADM K = K-hat + 2 Theta (profiles.dat); G_L2_R and Theta_L2_R are the norms "
     "of G^r = Delta^r - Delta_gamma^r and of Theta in the areal window, Theta_L2_ext in the "
     "coordinate one\n"},
    {Formulation::bssn_eulerian, n_bssn_rows, 0.0, {}, ""},
}};

constexpr const FormulationTraits& traits(Formulation f) {
  return formulations[static_cast<std::size_t>(f)];
}

/// How many variables formulation f evolves: the registry's first rows.
constexpr std::size_t n_evolved(Formulation f) {
  return traits(f).n_fields;
}

/// The registry rows formulation f evolves, in order.
constexpr std::span<const VarInfo> evolved(Formulation f) {
  return traits(f).rows();
}

/// The ADM K from K's row and Theta's (Theta is read only where the formulation needs it).
constexpr double adm_K(const FormulationTraits& f, double K_row, double Theta) {
  return f.K_is_adm() ? K_row : K_row + f.adm_K_theta * Theta;
}

/// What a matter model declares: the registry rows it evolves after its formulation's, and
/// its own series columns (after the formulation's) with their legend line.
struct MatterTraits {
  Matter matter;
  std::span<const Var> rows;
  std::span<const std::string_view> extra_series;
  std::string_view series_legend;
};

inline constexpr std::array<Var, 2> scalar_field_rows{Var::Phi, Var::Pi};
inline constexpr std::array<std::string_view, 2> scalar_field_series{"Phi_center", "Pi_center"};

/// One row per Matter, in enum order: vacuum, none; the scalar field (Sec. 19), Phi and Pi.
inline constexpr std::array<MatterTraits, 2> matters{{
    {Matter::none, {}, {}, ""},
    {Matter::scalar, scalar_field_rows, scalar_field_series,
     "the scalar field: Phi_center and Pi_center are Phi and Pi at r = 0 (as alpha_center: "
     "extrapolated from the two innermost cells in r^2, on the finest box)\n"},
}};

constexpr const MatterTraits& traits(Matter m) {
  return matters[static_cast<std::size_t>(m)];
}

namespace detail {

/// The rows of a formulation with a matter model, in a state's order, and each variable's slot.
struct FieldsLayout {
  std::array<VarInfo, n_vars> rows{};
  std::size_t n = 0;
  std::array<std::size_t, n_vars> slot{}; ///< n_vars: not held
};

constexpr FieldsLayout layout_of(Formulation f, Matter m) {
  FieldsLayout l;
  for (auto& s : l.slot)
    s = n_vars;
  for (std::size_t k = 0; k < formulations[static_cast<std::size_t>(f)].n_fields; ++k)
    l.rows[l.n++] = registry[k];
  for (const Var v : matters[static_cast<std::size_t>(m)].rows)
    l.rows[l.n++] = registry[index(v)];
  for (std::size_t k = 0; k < l.n; ++k)
    l.slot[index(l.rows[k].var)] = k;
  return l;
}

inline constexpr std::size_t n_matters = matters.size();

/// Every formulation with every matter model: formulation-major.
inline constexpr std::array<FieldsLayout, formulations.size() * n_matters> field_layouts{
    layout_of(Formulation::bssn, Matter::none),
    layout_of(Formulation::bssn, Matter::scalar),
    layout_of(Formulation::z4c, Matter::none),
    layout_of(Formulation::z4c, Matter::scalar),
    layout_of(Formulation::bssn_eulerian, Matter::none),
    layout_of(Formulation::bssn_eulerian, Matter::scalar)};

} // namespace detail

/// The rows a state holds, declared: its formulation's, then its matter's. A state, a right-hand
/// side and a file of values carry it as a tag; where a variable's row lies in a state is its
/// slot (the registry's index for the formulation's rows; after them for the matter's).
struct Fields {
  constexpr Fields() = default;
  /// The formulation in vacuum (implicit: a formulation alone is its vacuum fields).
  constexpr Fields(Formulation f, Matter m = Matter::none) : formulation(f), matter(m) {}

  /// The registry rows, in the order a state holds them.
  constexpr std::span<const VarInfo> rows() const { return {layout().rows.data(), layout().n}; }
  constexpr std::size_t size() const { return layout().n; }
  /// Whether a state of these fields holds v.
  constexpr bool holds(Var v) const { return layout().slot[index(v)] < n_vars; }
  /// The position of v's row (n_vars for a variable not held).
  constexpr std::size_t slot(Var v) const { return layout().slot[index(v)]; }
  friend constexpr bool operator==(const Fields&, const Fields&) = default;

  Formulation formulation = Formulation::bssn;
  Matter matter = Matter::none;

private:
  constexpr const detail::FieldsLayout& layout() const {
    return detail::field_layouts[static_cast<std::size_t>(formulation) * detail::n_matters
                                 + static_cast<std::size_t>(matter)];
  }
};

// The vacuum fields of a formulation are its registry prefix: their slots are the registry's.
static_assert(Fields(Formulation::z4c).slot(Var::Theta) == index(Var::Theta)
              && Fields(Formulation::bssn, Matter::scalar).slot(Var::Phi) == n_bssn_rows
              && !Fields(Formulation::bssn).holds(Var::Phi));

/// One number per evolved variable, indexed by the registry: values[index(v)] is v's.
struct PerVar {
  std::array<double, n_vars> values;
  constexpr double& operator[](Var v) { return values[index(v)]; }
  constexpr double operator[](Var v) const { return values[index(v)]; }
};

/// The registry entry with the given printed name, if any.
constexpr std::optional<Var> var_from_name(std::string_view name) {
  for (const auto& entry : registry)
    if (entry.name == name)
      return entry.var;
  return std::nullopt;
}

// The formulations' table must list them in enum order.
static_assert(formulations[0].formulation == Formulation::bssn
              && formulations[1].formulation == Formulation::z4c
              && formulations[2].formulation == Formulation::bssn_eulerian);

// The registry must list the variables in enum order.
static_assert([] {
  for (std::size_t i = 0; i < n_vars; ++i)
    if (index(registry[i].var) != i)
      return false;
  return true;
}());

} // namespace gbssn1d
