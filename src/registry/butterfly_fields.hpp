#pragma once
// The model-file form and fit options the butterfly strain models share (butterfly_strain,
// butterfly_strain_creep): the Preisach polarisation's fields, the strain map's, and the options
// of the switching part's fit.

#include "field_table.hpp"
#include "hyst/identify/fit_butterfly_strain.hpp"
#include "hyst/models/butterfly_strain.hpp"
#include "hyst/models/preisach.hpp"
#include "preisach_state_json.hpp"

namespace hyst::detail {

inline FieldTable<Preisach::Params> polarisation_table() {
  using Q = Preisach::Params;
  return FieldTable<Q>()
      .add_all(&Q::everett, relay_grid_everett_table("P units"))
      .add("polarisation_offset", &Q::offset, "P units", "offset of the polarisation",
           Presence::optional)
      .add("initial_state", &Q::initial_state, preisach_initial_state_from_string,
           "negative_saturation, positive_saturation or demagnetised", Presence::optional);
}

// The polarisation's fields, then the map's: y_off + d v + sum q_n P^n.
inline FieldTable<ButterflyStrain::Params> butterfly_strain_fields() {
  using P = ButterflyStrain::Params;
  return FieldTable<P>()
      .add_all(&P::polarisation, polarisation_table())
      .add("field_coefficient", &P::field_coefficient, "output / input units",
           "d of the linear term in the input", Presence::optional)
      .add("polarisation_coefficients", &P::polarisation_coefficients, "output units / P units^n",
           "q_1 .. q_N of the polynomial in P")
      .add("offset", &P::offset, "output units", "y_off", Presence::optional);
}

inline FieldTable<ButterflyFitOptions> butterfly_fit_option_table() {
  using O = ButterflyFitOptions;
  return add_grid_options(FieldTable<O>(Presence::optional),
                          "threshold levels of the polarisation's relay grid")
      .add("degree", &O::degree, "", "degree N of the polynomial in P")
      .add("fit_field_term", &O::fit_field_term, "", "fit the linear term d v")
      .add("initial_state", &O::start, butterfly_fit_start_from_string,
           "periodic (the record is one period in steady state) or a Preisach initial state")
      .add("max_iterations", &O::max_iterations, "", "Levenberg-Marquardt iterations");
}

}  // namespace hyst::detail
