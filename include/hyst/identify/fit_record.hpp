#pragma once
//! \file
//! One measured input/output record, e.g. one loop: what the fitters that take several records
//! (GPI, Jiles-Atherton) fit and validate on.

#include <span>

namespace hyst {

//! A record's samples, viewed (the caller keeps them alive during the fit).
struct FitRecord {
  std::span<const double> input;   //!< [input units], e.g. H [A/m]
  std::span<const double> output;  //!< [output units], same length, e.g. B [T]
};

}  // namespace hyst
