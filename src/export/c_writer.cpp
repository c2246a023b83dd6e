#include "c_writer.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string_view>

#include <fmt/format.h>

namespace hyst::detail {
namespace {

// A literal that C reads as floating point: "1" becomes "1.0".
std::string with_point(std::string text) {
  // A plain loop: find_first_of calls memchr on the set once per character (5 10^6 numbers for a
  // PI of 10^6 operators).
  const bool has_point = std::any_of(text.begin(), text.end(), [](char c) {
    return c == '.' || c == 'e' || c == 'E' || c == 'n';
  });
  if (!has_point) text += ".0";
  return text;
}

bool is_identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

}  // namespace

std::uint64_t text_digest(std::initializer_list<std::string_view> parts) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const std::string_view part : parts) {
    for (const char c : part) {
      hash ^= static_cast<unsigned char>(c);
      hash *= 0x100000001b3ULL;
    }
  }
  return hash;
}

std::string CWriter::number(double value) const {
  if (std::isinf(value)) {
    return fmt::format("{}HUGE_VAL{}", value < 0.0 ? "-" : "", single() ? "F" : "");
  }
  if (single()) return with_point(fmt::format("{:.9g}", static_cast<float>(value))) + "f";
  return with_point(fmt::format("{:.17g}", value));
}

std::string CWriter::table(std::span<const double> values) const {
  constexpr std::size_t per_line = 4;
  std::string text = "{";
  text.reserve(2 + values.size() * 26);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ',';
    text += i % per_line == 0 ? "\n      " : " ";
    text += number(values[i]);
  }
  text += '}';
  return text;
}

// Both run once over texts that hold the tables (tens of MB for 10^6 operators): copies of the
// plain runs between the marks, never per-character appends or in-place replacements (which
// moved the rest of the text once per mark).
std::string CWriter::expand(std::string_view text) const {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  std::size_t i = 0;
  while (i < text.size()) {
    // A plain loop: find_first_of calls memchr on the set once per character of the text.
    std::size_t mark = i;
    while (mark < text.size() && text[mark] != '@' && text[mark] != '$' && text[mark] != '#')
      ++mark;
    out.append(text.substr(i, mark - i));
    if (mark == text.size()) break;
    i = mark;
    const char c = text[i];
    if (c == '@') {
      out += prefix_;
    } else if (c == '$') {
      std::size_t end = i + 1;
      while (end < text.size() && is_identifier_char(text[end]))
        ++end;
      out += text.substr(i + 1, end - i - 1);
      if (single()) out += 'f';
      i = end - 1;
    } else if (c == '#' && i + 1 < text.size() && text[i + 1] == '(') {
      const std::size_t close = text.find(')', i);
      out += with_point(std::string(text.substr(i + 2, close - i - 2)));
      if (single()) out += 'f';
      i = close;
    } else {
      out += c;
    }
    ++i;
  }
  return out;
}

std::string CWriter::fill(std::string_view text,
                          std::initializer_list<std::pair<std::string_view, std::string>> values) {
  std::string out;
  std::size_t size = text.size();
  for (const auto& value : values)
    size += value.second.size();
  out.reserve(size);
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t open = text.find('%', i);
    if (open == std::string_view::npos) {
      out.append(text.substr(i));
      break;
    }
    out.append(text.substr(i, open - i));
    const std::size_t close = text.find('%', open + 1);
    const std::string_view name = close == std::string_view::npos
                                      ? std::string_view()
                                      : text.substr(open + 1, close - open - 1);
    const auto* match = std::find_if(values.begin(), values.end(),
                                     [&](const auto& value) { return value.first == name; });
    if (close != std::string_view::npos && match != values.end()) {
      out += match->second;
      i = close + 1;
    } else {
      out += '%';
      i = open + 1;
    }
  }
  return out;
}

std::string_view c_play_functions() {
  return R"(/* One play operator, w = max(v - r, min(v + r, w_previous)), with the branch rule of
   std::max/std::min as in the library's play_step(). */
static @_real @_play(@_real input, @_real threshold, @_real previous) {
  const @_real upper = input + threshold;
  const @_real lower = input - threshold;
  const @_real clipped = previous < upper ? previous : upper;
  return lower < clipped ? clipped : lower;
}

/* n plays updated in place, then offset + sum_j weights[j] play[j] (j in order). */
static @_real @_play_sum(const @_real *thresholds, const @_real *weights, @_real offset,
                         @_real *play, unsigned int n, @_real input) {
  @_real sum = #(0.0);
  unsigned int j;
  for (j = 0; j < n; ++j) play[j] = @_play(input, thresholds[j], play[j]);
  for (j = 0; j < n; ++j) sum += weights[j] * play[j];
  return offset + sum;
}

)";
}

std::string c_model_declarations(std::string_view reset_note, std::string_view step_note) {
  return CWriter::fill(R"(
/* The fitted parameters. */
extern const @_params @_PARAMS;

/* The state stored in the model file. */
void @_init(@_state *state);
/* The model's default initial state (%RESET%). */
void @_reset(@_state *state);
/* One sample: %STEP% */
@_real @_step(const @_params *params, @_state *state, @_real input);
)",
                       {{"RESET", std::string(reset_note)}, {"STEP", std::string(step_note)}});
}

std::string c_inverse_declarations(std::string_view step_note) {
  return CWriter::fill(R"(
/* The inverse's parameters, computed by the library from the fitted ones. */
extern const @_inverse_params @_INVERSE_PARAMS;

/* Inverse in the state consistent with the model file's state (as `hyst invert` starts it). */
void @_inverse_init(@_inverse_state *state);
/* Inverse in the state consistent with the model's default initial state. */
void @_inverse_reset(@_inverse_state *state);
/* The input that makes the model produce `target`%STEP%; advances the inverse's state.
   A target out of reach, +-inf included, gives the extreme input in its direction (the input
   limit, or without one a finite input far out); a NaN target returns the last input again and
   leaves the inverse's state as it was (a model with lags steps them on). Never NaN. */
@_real @_inverse_step(const @_inverse_params *params, @_inverse_state *state, @_real target);
)",
                       {{"STEP", std::string(step_note)}});
}

CCode assemble_c_files(const CWriter& writer, const CModelCode& code,
                       std::string_view source_file) {
  std::string guard_base;
  for (const char c : writer.prefix())
    guard_base += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::string guard = guard_base + "_H_INCLUDED";
  const std::string origin =
      source_file.empty() ? std::string("a model object") : fmt::format("'{}'", source_file);
  const std::string preamble = fmt::format(
      " * {}\n"
      " * Exported by hyst from {}; regenerate it instead of editing it:\n"
      " *     hyst export --model FILE --lang c --out DIR --prefix {}{}\n"
      " *\n"
      "{}"
      " *\n"
      " * Scalar type: {}.\n"
      " * Plain C99: no heap, no library beyond <math.h>, no recursion, every loop bounded by a\n"
      " * size fixed at export time, tables const.\n"
      " */\n",
      code.title, origin, writer.prefix(), writer.single() ? " --float" : "", code.description,
      writer.single() ? "float (every operation in single precision)"
                      : "double (reproduces the library's step to rounding)");

  CCode files;
  files.header_name = writer.prefix() + ".h";
  files.source_name = writer.prefix() + ".c";
  files.has_inverse = code.has_inverse;
  files.parameters = code.parameters;
  files.inverse_parameters = code.inverse_parameters;
  files.sample_time = code.sample_time;
  if (code.resamplable) files.set_sample_time = writer.prefix() + "_set_sample_time";
  files.state_check = writer.expand(code.state_check);
  files.inverse_state_check = writer.expand(code.inverse_state_check);
  const std::string declarations = writer.expand(code.header);
  const std::string definitions = writer.expand(code.source);
  const std::string stamp_name = guard_base + "_EXPORT_STAMP";
  const std::uint64_t stamp = text_digest({preamble, declarations, definitions});
  files.header = fmt::format(
      "/* {}: declarations.\n{}\n#ifndef {}\n#define {}\n\n"
      "/* Digest of this export; {} checks it. */\n#define {} 0x{:016x}ULL\n\n"
      "#ifdef __cplusplus\nextern \"C\" {{\n"
      "#endif\n\ntypedef {} {}_real;\n\n{}\n#ifdef __cplusplus\n}}\n#endif\n\n#endif /* {} */\n",
      files.header_name, preamble, guard, guard, files.source_name, stamp_name, stamp,
      writer.single() ? "float" : "double", writer.prefix(), declarations, guard);
  files.source = fmt::format(
      "/* {}: tables and functions.\n{}\n#include \"{}\"\n\n"
      "/* A header from another export (e.g. after an interrupted one) must not build. */\n"
      "#if !defined({}) || {} != 0x{:016x}ULL\n"
      "#error \"{} and {} come from different exports: export the model again\"\n#endif\n\n"
      "#include <math.h>\n\n{}",
      files.source_name, preamble, files.header_name, stamp_name, stamp_name, stamp,
      files.header_name, files.source_name, definitions);
  return files;
}

double c_gain(std::span<const double> weights) {
  double sum = 0.0;
  for (const double w : weights)
    sum += std::abs(w);
  return std::max(1.0, sum);
}

std::string c_inverse_target_functions(const CWriter& writer, double gain) {
  // No sum of the inverse overflows below it (every partial sum stays below a quarter of the
  // largest number), and it lies far beyond any output a model reaches.
  const double largest =
      writer.single() ? std::numeric_limits<float>::max() : std::numeric_limits<double>::max();
  return CWriter::fill(
      R"(/* Targets beyond +-@_TARGET_LIMIT (and +-inf) are taken as +-@_TARGET_LIMIT: they give the
   extreme input in their direction, never inf - inf = NaN inside the inverse's sums. */
#define @_TARGET_LIMIT %LIMIT%
static @_real @_bounded_target(@_real target) {
  if (target > @_TARGET_LIMIT) return @_TARGET_LIMIT;
  if (target < -@_TARGET_LIMIT) return -@_TARGET_LIMIT;
  return target;
}

/* The inverse's input limits (the library's below_range / above_range answers), written so that
   NaN cannot pass: it gives input_min. */
static @_real @_clamp(@_real input, @_real input_min, @_real input_max) {
  if (!(input >= input_min)) return input_min;
  if (input > input_max) return input_max;
  return input;
}

)",
      {{"LIMIT", writer.number(0.25 * largest / gain)}});
}

std::string_view c_dead_zone_function() {
  return R"(/* S(x) = sum_i g_i S_{d_i}(x), S_d(x) = max(x - d, 0) for d > 0, x for d = 0, min(x - d, 0)
   for d < 0 (the library's DeadZoneSuperposition, i in order). */
static @_real @_dead_zones(const @_real *thresholds, const @_real *weights, @_real x) {
  @_real y = #(0.0);
  unsigned int i;
  for (i = 0; i < @_DEAD_ZONES; ++i) {
    const @_real d = thresholds[i];
    @_real zone = x;
    if (d > #(0.0)) {
      zone = x - d < #(0.0) ? #(0.0) : x - d;
    } else if (d < #(0.0)) {
      zone = #(0.0) < x - d ? #(0.0) : x - d;
    }
    y += weights[i] * zone;
  }
  return y;
}

)";
  ;
}

CParameterField c_scalar(std::string name, double value, CUnit unit, std::string description,
                         CRule rule) {
  return {std::move(name), {value}, false, unit, std::move(description), rule};
}

CParameterField c_array(std::string name, std::span<const double> values, CUnit unit,
                        std::string description, CRule rule) {
  return {
      std::move(name), {values.begin(), values.end()}, true, unit, std::move(description), rule};
}

std::string c_output_limits(const CWriter& writer, double output_min, double output_max) {
  std::string text;
  if (std::isfinite(output_min)) {
    text +=
        CWriter::fill("  if (output < %L%) output = %L%;\n", {{"L", writer.number(output_min)}});
  }
  if (std::isfinite(output_max)) {
    text +=
        CWriter::fill("  if (output > %U%) output = %U%;\n", {{"U", writer.number(output_max)}});
  }
  return text;
}

}  // namespace hyst::detail
