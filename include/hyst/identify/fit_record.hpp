#pragma once
//! \file
//! One measured input/output record, e.g. one loop or one reversal curve: what every fitter that
//! takes several records (GPI, Jiles-Atherton, the Bouc-Wen oscillator, the FORC fit of the
//! Preisach model) fits and validates on.

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace hyst {

//! A record's samples, viewed (the caller keeps them alive during the fit).
struct FitRecord {
  std::span<const double> input;   //!< [input units], e.g. H [A/m]; oversampling * N samples
  std::span<const double> output;  //!< [output units], e.g. B [T]; N samples
  //! Input samples per output sample (>= 1): output[k] belongs to input[k * oversampling]. Only
  //! the Bouc-Wen oscillator fit, which simulates between output samples, takes more than 1.
  std::size_t oversampling = 1;
  //! Leading output samples not compared (a transient), < N. Only the Bouc-Wen oscillator fit
  //! takes more than 0; the others start their records in a stated state instead.
  std::size_t skip = 0;
};

//! Views of records whose samples are kept elsewhere: any struct with `input` and `output`
//! sequences, e.g. curves read from a file into vectors. The views live as long as `owned`.
template <class Owned>
std::vector<FitRecord> fit_records_of(const std::vector<Owned>& owned) {
  std::vector<FitRecord> records;
  records.reserve(owned.size());
  for (const auto& record : owned)
    records.push_back({record.input, record.output});
  return records;
}

//! What a fitter accepts of a record beyond matching, finite, non-empty samples.
struct FitRecordRules {
  std::size_t min_samples = 1;  //!< output samples (compared ones, after `skip`)
  bool oversampling = false;    //!< oversampling > 1 allowed
  bool skip = false;            //!< skip > 0 allowed
};

//! Throws hyst::Error naming `name` (e.g. "records[2]") and its member when the record breaks the
//! rules: lengths, non-finite samples, too few samples, an oversampling or skip the fitter does
//! not take.
void check_fit_record(const FitRecord& record, std::string_view name, const FitRecordRules& rules);

}  // namespace hyst
