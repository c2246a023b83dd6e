// The command line of the hyst library (see main.cpp): the application with its subcommands,
// parsing, and the translation of every failure into one error line and an exit status.

#include <atomic>
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli_app.hpp"
#include "commands/commands.hpp"
#include "hyst/core/error.hpp"

#ifndef HYST_VERSION
#define HYST_VERSION "unknown"
#endif

namespace hyst::cli {
namespace {

std::atomic<std::size_t> failed_allocation_bytes{0};

//! "an allocation of 3.2 GB (3200000000 bytes) failed", or nothing when the size is unknown.
std::string failed_allocation_text() {
  const std::size_t bytes = failed_allocation_bytes.load();
  if (bytes == 0) return "";
  return fmt::format(": an allocation of {:.3g} GB ({} bytes) failed",
                     static_cast<double>(bytes) / 1e9, bytes);
}

void print_error(std::string_view message) {
  std::fflush(stdout);
  fmt::print(stderr, "hyst: error: {}\n", one_line(message));
}

//! "hyst fit" for the innermost subcommand on the command line, "hyst" without one.
std::string command_path(const CLI::App& app) {
  std::string path = app.get_name();
  const CLI::App* current = &app;
  while (true) {
    const auto selected = current->get_subcommands();
    if (selected.empty()) return path;
    current = selected.front();
    path += " " + current->get_name();
  }
}

int parse_and_run(int argc, const char* const* argv) {
  CLI::App app{
      "hyst: hysteresis models from the command line - list the models, simulate one from a "
      "model file, fit one to measured data, invert it, plot data and models.",
      "hyst"};
  app.set_version_flag("--version", std::string("hyst ") + HYST_VERSION);
  app.require_subcommand(1);
  app.get_formatter()->column_width(34);
  app.footer(R"(Examples:
  hyst models                                   list the models
  hyst models pi                                parameters, fit options, an example model file
  hyst fit pi --data d.csv --input v --output y --out m.json --validate-fraction 0.2
  hyst simulate --model m.json --input v.csv --out y.csv
  hyst compare --data d.csv --input v --output y --out-dir cmp   rank the models
  hyst invert --model m.json --target y.csv --out v.csv --input-min -10 --input-max 10
  hyst plot --data d.csv --x v --y y --kind loop --model m.json --out loop.png
  hyst info m.json
  hyst data info RMN_TRAP_SLOW.dat              tables, columns, units, reversals, cycles
  hyst fit-system --order 28 --sample-time 1.5625e-4 --input-npy u.npy --output-npy y.npy --out s.json
  hyst evaluate --model s.json --input-npy u_test.npy --output-npy y_test.npy --periodic
  hyst batch fit --model pi --data 'd/*.csv' --input v --output y --out fits/   one fit per record (Dask)
Run 'hyst <command> --help' for the options of a command.
Exit status: 0 success, 1 failure, 2 usage error; errors are one line 'hyst: error: ...' on stderr.)");

  add_models_command(app);
  add_simulate_command(app);
  add_fit_command(app);
  add_invert_command(app);
  add_plot_command(app);
  add_info_command(app);
  add_actuator_command(app);
  add_data_command(app);
  add_export_command(app);
  add_compare_command(app);
  add_fit_system_command(app);
  add_evaluate_command(app);
  add_batch_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {
    return app.exit(success);  // --help, --version: printed to stdout, exit 0
  } catch (const CLI::ParseError& error) {
    // CLI11 reports a misspelt command as "A subcommand is required"; name it instead.
    if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-') {
      std::string commands;
      for (const auto* command : app.get_subcommands({})) {
        commands += (commands.empty() ? "" : ", ") + command->get_name();
      }
      print_error(
          fmt::format("unknown command '{}' (commands: {}; see 'hyst --help')", argv[1], commands));
    } else {
      print_error(fmt::format("{} (see '{} --help')", error.what(), command_path(app)));
    }
    return kUsage;
  }
  return kSuccess;
}

}  // namespace

void note_failed_allocation(std::size_t bytes) noexcept {
  failed_allocation_bytes.store(bytes);
}

int run_cli(int argc, const char* const* argv) {
  try {
    return parse_and_run(argc, argv);
  } catch (const hyst::Error& error) {
    print_error(error.what());
  } catch (const std::bad_alloc&) {
    // The big reads name their file and size themselves; this is the last resort.
    std::string command;
    for (int k = 1; k < argc; ++k)
      command += fmt::format("{}{}", k > 1 ? " " : "", argv[k]);
    if (command.size() > 200) command = command.substr(0, 200) + "...";
    print_error(
        fmt::format("out of memory running 'hyst {}'{}", command, failed_allocation_text()));
  } catch (const std::exception& error) {
    print_error(fmt::format("unexpected failure: {}", error.what()));
  } catch (...) {
    print_error("unexpected failure of an unknown kind");
  }
  return kFailure;
}

}  // namespace hyst::cli
