#pragma once
//! \file
//! How a fit with creep lags treats the lags its records cannot identify
//! (fit_prandtl_ishlinskii_creep.hpp has the penalty and its scaling).

#include <string_view>

namespace hyst {

enum class CreepLaw {
  //! Every creep weight free (>= 0), time constants within the records' duration.
  free,
  //! Time constants far beyond the records, weights held smooth in log tau: a logarithmic creep
  //! law wherever the records do not say otherwise.
  logarithmic,
};

//! "free" or "logarithmic"; throws hyst::Error naming the accepted words otherwise.
CreepLaw creep_law_from_string(std::string_view text);
//! The word creep_law_from_string() reads.
std::string_view to_string(CreepLaw law);

}  // namespace hyst
