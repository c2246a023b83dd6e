// hyst export: a model file (and its inverse) as dependency-free C code for a real-time
// controller, or as an FMI 2.0 co-simulation FMU for simulation tools.

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "hyst/export/export_c.hpp"
#include "hyst/export/export_fmu.hpp"
#include "hyst/registry/fitted_domain_file.hpp"
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
  // FMU only.
  bool with_inverse = false;
  std::string input_name = "u";
  std::string output_name = "y";
  std::string input_unit;
  std::string output_unit;
  std::string compiler;
};

void write_fmu(const ExportOptions& options, const DynamicModel& model,
               const CExportOptions& code_options) {
  FmuExportOptions fmu_options;
  fmu_options.code = code_options;
  fmu_options.inverse = options.with_inverse;
  fmu_options.input_name = options.input_name;
  fmu_options.output_name = options.output_name;
  fmu_options.input_unit = options.input_unit;
  fmu_options.output_unit = options.output_unit;
  fmu_options.compiler = options.compiler;
  const auto folder = std::filesystem::path(options.out);
  const std::string prefix = c_export_prefix(model, code_options);
  std::vector<io::NamedPath> outputs{{folder / (prefix + ".fmu"), "--out"}};
  if (options.with_inverse) outputs.push_back({folder / (prefix + "_inverse.fmu"), "--out"});
  io::check_outputs({{options.model, "--model"}}, outputs);
  const FmuFiles files = export_fmu(model, folder, fmu_options);
  fmt::print(
      "wrote {}{}: FMI 2.0 co-simulation, the {} model in {}\n", files.model.string(),
      files.inverse.empty() ? "" : fmt::format(" and {} (its inverse)", files.inverse.string()),
      model.name(), options.single ? "float" : "double");
}

void run(const ExportOptions& options) {
  if (options.lang != "c" && options.lang != "fmu") {
    throw Error(fmt::format("--lang '{}' is not supported (c or fmu)", options.lang));
  }
  if (options.lang == "c" && (options.with_inverse || !options.input_unit.empty() ||
                              !options.output_unit.empty() || !options.compiler.empty())) {
    throw Error("--with-inverse, --input-unit, --output-unit and --cc are for --lang fmu");
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
  if (options.lang == "fmu") {
    try {
      write_fmu(options, *model, export_options);
    } catch (const Error& error) {
      throw Error(fmt::format("{}: {}", options.model, error.what()));
    }
    return;
  }
  // The C code counts inputs beyond the domain the model was fitted on, when its file has one.
  export_options.domain = load_fitted_domain(options.model);
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
      "export",
      "Write a model (and its inverse) as dependency-free C99 code for a controller, or as an "
      "FMI 2.0 co-simulation FMU for simulation tools.");
  command->add_option("--model", options->model, "Model file (JSON)")->required();
  command->add_option("--lang", options->lang, "c (C99 sources) or fmu (FMI 2.0 co-simulation)")
      ->capture_default_str();
  command
      ->add_option("--out", options->out,
                   "Output folder for <prefix>.h and .c, or <prefix>.fmu (created when missing)")
      ->required();
  command->add_option("--prefix", options->prefix,
                      "Prefix of the C names and files (default: hyst_<model>)");
  command->add_flag("--float", options->single, "Single precision (float) code");
  command->add_flag("--double", options->double_precision, "Double precision code (default)");
  command->add_option("--input-min", options->input_min,
                      "Lowest input the inverse may return (default: none)");
  command->add_option("--input-max", options->input_max,
                      "Highest input the inverse may return (default: none)");
  command->add_flag("--with-inverse", options->with_inverse,
                    "FMU: also write the inverse compensator's FMU, <prefix>_inverse.fmu");
  command->add_option("--input-name", options->input_name, "FMU: the input variable's name")
      ->capture_default_str();
  command->add_option("--output-name", options->output_name, "FMU: the output variable's name")
      ->capture_default_str();
  command->add_option("--input-unit", options->input_unit, "FMU: the input's unit, e.g. V");
  command->add_option("--output-unit", options->output_unit, "FMU: the output's unit, e.g. um");
  command->add_option("--cc", options->compiler,
                      "FMU: the C compiler that builds its binary (default: $CC, else cc)");
  command->footer(R"(Examples:
  hyst export --model m.json --lang c --out ctrl/ --prefix piezo
      writes ctrl/piezo.h and ctrl/piezo.c: piezo_PARAMS, piezo_init/reset/step and, when the
      model has an inverse, piezo_inverse_init/reset/step. Supported models: pi, gpi,
      modified_pi, preisach, bouc_wen, pi_creep, modified_pi_creep. The code needs only
      <math.h> (link with -lm). When the model file has the domain it was fitted on
      (info.domain, written by hyst fit), the code also has piezo_DOMAIN and
      piezo_check_input (piezo_check_target with an inverse): each returns 1 for a sample
      inside it (widened by 5 % of its width), else 0, and counts it in a piezo_domain_status.
  hyst export --model m.json --lang fmu --out fmus/ --prefix piezo --input-unit V \
      --output-unit um --with-inverse
      writes fmus/piezo.fmu and fmus/piezo_inverse.fmu (FMI 2.0 co-simulation, linux64 binary
      built with the C compiler of this machine): input u, output y, the fitted values as
      parameters.)");
  command->callback([options] { run(*options); });
}

}  // namespace hyst::cli
