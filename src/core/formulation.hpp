// Which evolution equations: a parameter that configurations name without the table of
// variables (core/registry.hpp says which variables each formulation evolves).
#pragma once

namespace gbssn1d {

/// BSSN (equations document, Sec. 2-3) or Z4c with constraint damping (Sec. 17), which evolves
/// Theta besides, and K-hat = K - 2 Theta in K's place.
enum class Formulation { bssn, z4c };

} // namespace gbssn1d
