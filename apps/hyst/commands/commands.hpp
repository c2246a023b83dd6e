#pragma once
// The subcommands of the `hyst` command line, one file each. Every add_*_command() adds its
// subcommand to the application with a callback that does the work; main.cpp parses the command
// line and turns every exception into one "hyst: error: ..." line (see main.cpp).

#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/output_paths.hpp"

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
void add_evaluate_command(CLI::App& app);
void add_fit_system_command(CLI::App& app);
void add_batch_command(CLI::App& app);

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

//! Creates the output folder of `option` (e.g. --out-dir) and its parents when missing, before
//! the outputs in it are checked.
inline void create_output_folder(const std::filesystem::path& folder, std::string_view option) {
  try {
    io::create_output_folder(folder);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", option, error.what()));
  }
}

//! "-" names standard output for the text outputs of the command line.
inline bool is_stdout(std::string_view path) {
  return path == "-";
}

//! Refuses "-" for an output that is not text (an image).
inline void refuse_stdout(std::string_view path, std::string_view option) {
  if (is_stdout(path)) {
    throw Error(
        fmt::format("{} '-': standard output is for text outputs only; name a file", option));
  }
}

//! Writes a text output: to standard output for "-", else atomically to the file.
inline void write_text_output(const std::string& path, std::string_view text) {
  if (!is_stdout(path)) {
    io::write_file_atomically(path, text);
    return;
  }
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
    throw Error("cannot write to standard output");
  }
}

//! One text output of a command: its path ("-": standard output) and its content.
struct TextOutput {
  std::string path;
  std::string_view text;
};

//! Writes the text outputs of one command together: the files as io::write_files_atomically()
//! does (all contents flushed before the first rename), then the ones for standard output.
inline void write_text_outputs(std::initializer_list<TextOutput> outputs) {
  std::vector<io::FileContent> files;
  for (const auto& output : outputs)
    if (!is_stdout(output.path)) files.push_back({output.path, output.text});
  io::write_files_atomically(files);
  for (const auto& output : outputs)
    if (is_stdout(output.path)) write_text_output(output.path, output.text);
}

//! Where the "wrote ..." messages go: standard error when standard output carries an output.
inline std::FILE* message_stream(bool output_on_stdout) {
  return output_on_stdout ? stderr : stdout;
}

}  // namespace hyst::cli
