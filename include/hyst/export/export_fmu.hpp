#pragma once
//! \file
//! Export of a model (and, on request, its inverse compensator) as a Functional Mock-up Unit for
//! co-simulation (FMI 2.0): the unit that Simulink, OpenModelica, Dymola and Python co-simulation
//! tools import.
//!
//! An FMU is a zip archive holding `modelDescription.xml`, the C sources (the C export of
//! export_c.hpp, a generated FMI 2.0 wrapper and the FMI declarations it is built against) and
//! `binaries/linux64/<identifier>.so`, compiled at export time by the C compiler given (or $CC,
//! or `cc`). Its variables: the input (value reference 0), the output (1) and the fitted
//! parameters (2, 3, ..., "name[k]" for element k of an array, counted from 1 as the FMI
//! structured naming convention does), each with its unit when the input and output units are
//! given. Parameters are `fixed`: they may be set before the FMU leaves initialisation mode.
//!
//! Timing. The output read at a communication point is the model's step for the input set there,
//! from the state the earlier points left (direct feedthrough, as the library's y_k = step(u_k));
//! fmi2DoStep keeps that state. A host that sets u_k, reads y_k and steps for k = 0, 1, ... gets
//! exactly the library's simulate(). A rate-independent model takes any communication step; the
//! creep models take only their fitted sample time (canHandleVariableCommunicationStepSize is
//! false and any other step is an error).
//!
//! The FMU can get, set and serialise its state (the hysteresis memory, the parameters, time and
//! input: plain values of a fixed size, checked against the export on reading), and gives
//! fmi2GetDirectionalDerivative of the output with respect to the input: the one-sided derivative
//! in the direction of the seed (a hysteresis operator's slope depends on the direction of the
//! input's change), as a difference quotient over a step of 1e-7 (1 + |u|) in double precision
//! (1e-3 in float), exact for the piecewise-linear models away from a threshold. A step does no
//! heap allocation; the instance and saved states are allocated through the importer's
//! callbacks.

#include <filesystem>
#include <string>

#include "hyst/export/c_code.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

struct FmuExportOptions {
  //! The C export's options; its prefix is the FMU's model identifier (the inverse's is
  //! "<prefix>_inverse").
  CExportOptions code;
  //! Names of the FMU's input and output variables (FMI names: a letter or '_', then letters,
  //! digits and '_'); for the inverse FMU they change roles (its input is the model's output).
  std::string input_name = "u";
  std::string output_name = "y";
  //! Units of the model's input and output, e.g. "V" and "um"; empty: the variables get none.
  std::string input_unit;
  std::string output_unit;
  //! Also write the inverse compensator's FMU (an error when the model has no inverse).
  bool inverse = false;
  //! The C compiler that builds the binary; empty: $CC, else "cc".
  std::string compiler;
};

//! The files export_fmu() wrote.
struct FmuFiles {
  std::filesystem::path model;    //!< <folder>/<prefix>.fmu
  std::filesystem::path inverse;  //!< <folder>/<prefix>_inverse.fmu, or empty
};

//! Generates, compiles and packs the FMU(s) of `model` in its current state into `folder`
//! (created when missing); the files are written together and atomically. Throws hyst::Error
//! naming the option for a bad name or unit ("input_name", "input_unit", ...), for a model
//! without C export (as generate_c()) or without inverse when one is asked for, and with the
//! compiler's messages when it fails or cannot be started.
FmuFiles export_fmu(const DynamicModel& model, const std::filesystem::path& folder,
                    const FmuExportOptions& options);

}  // namespace hyst
