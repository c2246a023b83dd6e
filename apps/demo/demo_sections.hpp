#pragma once
// The sections of the demo behind `make demo`, one file each. A section reads what it needs
// from the data folder, writes its plots and CSV files into the output folder and returns its
// part of results.md.

#include <filesystem>
#include <string>

// PI fit on measured piezo loops and inverse-PI compensation (piezo_section.cpp).
std::string piezo_section(const std::filesystem::path& data_dir,
                          const std::filesystem::path& folder);

// Closed-loop control of the simulated MSMA actuator: open loop, inverse feedforward, PID and
// PID + feedforward compared (actuator_section.cpp); `config_file` is the actuator's JSON.
std::string actuator_section(const std::filesystem::path& config_file,
                             const std::filesystem::path& folder);

// The seed paper's comparison of Ikuta's, the PI and the Preisach model on one input with
// internal loops (seed_comparison_section.cpp); needs no data.
std::string seed_comparison_section(const std::filesystem::path& folder);

// The PI model with creep against the rate-independent PI: fitted on one triangle at 1 and
// 0.1 Hz, predicting it at 0.01 Hz (creep_section.cpp).
std::string creep_section(const std::filesystem::path& data_dir,
                          const std::filesystem::path& folder);

// Every model with a fitter ranked on every measured record that has an input and an output
// (model_comparison_section.cpp): tables, plots and an HTML report per record.
std::string creep_hold_section(const std::filesystem::path& data_dir,
                               const std::filesystem::path& folder);

std::string model_comparison_section(const std::filesystem::path& data_dir,
                                     const std::filesystem::path& folder);
