// hyst: the command line of the hyst library. One subcommand per task (models, simulate, fit,
// invert, plot, info, actuator, data; apps/hyst/commands/), all built on the model registry and
// model files.
//
// Exit status: 0 on success (and for --help, --version), 1 when the work fails (invalid data or
// model files, unwritable output, ...), 2 for usage errors (unknown options, missing arguments).
// Every failure is reported as exactly one line on standard error, "hyst: error: <message>".

#include "cli_app.hpp"

int main(int argc, char** argv) {
  return hyst::cli::run_cli(argc, argv);
}
