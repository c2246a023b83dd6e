// hyst export: a model file (and its inverse) as dependency-free C code for a real-time
// controller.

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "hyst/export/export_c.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst::cli {
namespace {

struct ExportOptions {
  std::string model;
  std::string lang = "c";
  std::string out;
  std::string prefix;
  bool single = false;
  bool double_precision = false;
  double input_min = -std::numeric_limits<double>::infinity();
  double input_max = std::numeric_limits<double>::infinity();
};

void run(const ExportOptions& options) {
  if (options.lang != "c") {
    throw Error(fmt::format("--lang '{}' is not supported (only c)", options.lang));
  }
  if (options.single && options.double_precision) {
    throw Error("--float and --double exclude each other: choose one scalar type");
  }
  if (std::isnan(options.input_min) || std::isnan(options.input_max) ||
      !(options.input_min < options.input_max)) {
    throw Error(fmt::format("--input-min {} must be less than --input-max {}", options.input_min,
                            options.input_max));
  }
  const auto model = load_model(options.model);
  CExportOptions export_options;
  export_options.prefix = options.prefix;
  export_options.scalar = options.single ? CScalar::single_precision : CScalar::double_precision;
  export_options.limits = {options.input_min, options.input_max};
  export_options.source = std::filesystem::path(options.model).filename().string();
  CCode code;
  try {
    // The file names depend on the prefix: known once the code is generated.
    code = generate_c(*model, export_options);
    const auto folder = std::filesystem::path(options.out);
    io::check_outputs({{options.model, "--model"}},
                      {{folder / code.header_name, "--out"}, {folder / code.source_name, "--out"}});
    write_c(code, folder);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", options.model, error.what()));
  }
  const auto folder = std::filesystem::path(options.out);
  fmt::print("wrote {} and {}: the {} model{} in {}\n", (folder / code.header_name).string(),
             (folder / code.source_name).string(), model->name(),
             code.has_inverse ? " and its inverse" : "", options.single ? "float" : "double");
}

}  // namespace

void add_export_command(CLI::App& app) {
  auto options = std::make_shared<ExportOptions>();
  auto* command = app.add_subcommand(
      "export", "Write a model (and its inverse) as dependency-free C99 code for a controller.");
  command->add_option("--model", options->model, "Model file (JSON)")->required();
  command->add_option("--lang", options->lang, "Target language (c)")->capture_default_str();
  command
      ->add_option("--out", options->out,
                   "Output folder for <prefix>.h and .c (created when missing)")
      ->required();
  command->add_option("--prefix", options->prefix,
                      "Prefix of the C names and files (default: hyst_<model>)");
  command->add_flag("--float", options->single, "Single precision (float) code");
  command->add_flag("--double", options->double_precision, "Double precision code (default)");
  command->add_option("--input-min", options->input_min,
                      "Lowest input the inverse may return (default: none)");
  command->add_option("--input-max", options->input_max,
                      "Highest input the inverse may return (default: none)");
  command->footer(R"(Example:
  hyst export --model m.json --lang c --out ctrl/ --prefix piezo
      writes ctrl/piezo.h and ctrl/piezo.c: piezo_PARAMS, piezo_init/reset/step and, when the
      model has an inverse, piezo_inverse_init/reset/step. Supported models: pi, gpi,
      modified_pi, preisach, bouc_wen. The code needs only <math.h> (link with -lm).)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
