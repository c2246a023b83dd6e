#pragma once
// hyst fit preisach --forc FILE: the Preisach model identified from the first-order reversal
// curves of a MicroMag FORC file (hyst/registry/forc_fit.hpp), saved as a 'tabulated_preisach'
// model file with its fit report.

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace hyst::cli {

struct ForcFitArguments {
  std::string model;  //!< the model named on the command line
  std::string forc;   //!< --forc FILE
  std::string out;
  std::string report;
  std::string drift = "none";
  std::size_t hold_out_every = 0;
  nlohmann::json options;  //!< --options / --option
};

void run_forc_fit(const ForcFitArguments& arguments);

}  // namespace hyst::cli
