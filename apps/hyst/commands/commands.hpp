#pragma once
// The subcommands of the `hyst` command line, one file each. Every add_*_command() adds its
// subcommand to the application with a callback that does the work; main.cpp parses the command
// line and turns every exception into one "hyst: error: ..." line (see main.cpp).

#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "hyst/core/error.hpp"

namespace hyst::cli {

void add_models_command(CLI::App& app);
void add_simulate_command(CLI::App& app);
void add_fit_command(CLI::App& app);
void add_invert_command(CLI::App& app);
void add_plot_command(CLI::App& app);
void add_info_command(CLI::App& app);
void add_actuator_command(CLI::App& app);
void add_data_command(CLI::App& app);
void add_export_command(CLI::App& app);
void add_compare_command(CLI::App& app);

//! Text on one line: line breaks (and tabs) become single spaces, trailing space removed. Every
//! message of the command line goes through this, so that each is exactly one line.
inline std::string one_line(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const bool space = c == '\n' || c == '\r' || c == '\t';
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  while (!out.empty() && out.back() == ' ')
    out.pop_back();
  return out;
}

//! "hyst: warning: <message>" on standard error.
inline void warn(std::string_view message) {
  fmt::print(stderr, "hyst: warning: {}\n", one_line(message));
}

//! Fails early, before any long work, when an output file cannot be created because its folder
//! is missing or is not a folder.
inline void check_output_folder(const std::filesystem::path& path, std::string_view option) {
  const auto folder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  std::error_code error;
  const auto status = std::filesystem::status(folder, error);
  if (!std::filesystem::exists(status)) {
    throw Error(fmt::format("{} '{}': the folder '{}' does not exist", option, path.string(),
                            folder.string()));
  }
  if (!std::filesystem::is_directory(status)) {
    throw Error(
        fmt::format("{} '{}': '{}' is not a folder", option, path.string(), folder.string()));
  }
}

}  // namespace hyst::cli
