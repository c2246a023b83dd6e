#include "hyst/io/micromag_forc.hpp"

#include <cmath>
#include <cstddef>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/limits.hpp"
#include "line_reader.hpp"
#include "micromag_columns.hpp"
#include "micromag_lines.hpp"
#include "micromag_sections.hpp"
#include "text_encoding.hpp"
#include "text_fields.hpp"

namespace hyst::io {
namespace {

using detail::location;
using detail::parse_number;
using detail::trim;

struct Block {
  std::vector<std::vector<double>> columns;  //!< columns[j][i]: column j of row i
  std::vector<std::size_t> lines;            //!< 1-based line of each row
  std::size_t size() const { return lines.size(); }
};

class ForcParser {
 public:
  // A final line end ends the last line; it does not start an empty one (messages name the last
  // line of the text).
  ForcParser(std::string_view text, std::string_view source)
      : lines_(text.ends_with('\n') ? text.substr(0, text.size() - 1) : text), source_(source) {
    file_.source = std::string(source);
  }

  MicromagForcFile parse() {
    std::string_view line;
    if (!lines_.next(line) || !detail::is_micromag_format_line(line)) {
      throw Error(
          fmt::format("{}: not a MicroMag data file (the first line is '{}', expected "
                      "'MicroMag 2900/3900 Data File (Series ...)')",
                      location(source_, 1), trim(line)));
    }
    file_.format = std::string(trim(line));
    if (lines_.next(line)) file_.title = utf8_from_latin1(trim(line));
    if (file_.title.find("Hysteresis loop") != std::string::npos) {
      throw Error(fmt::format(
          "{}: a MicroMag hysteresis loop file, not a FORC file (read it with read_micromag_loop)",
          location(source_, 2)));
    }
    // One header reader for every layout: "key = value", "key : value" and "key   value"
    // entries in any order, then an optional segment table, then the data.
    detail::MicromagSectionReader sections(lines_, source_);
    static_cast<void>(sections.read_head(file_.header));
    const std::string_view first_row = sections.first_row();
    file_.layout = file_.header_text("NData") ? MicromagForcLayout::series_0015
                   : file_.header.empty()     ? MicromagForcLayout::no_header
                                              : MicromagForcLayout::series_0016;
    if (file_.layout == MicromagForcLayout::series_0015) {
      file_.columns = {"Field", "Moment"};
    } else {
      const auto count = detail::split_fields(first_row, ',').size();
      if (count < 2) {
        throw Error(fmt::format("{}: a data row needs at least field and moment, got '{}'",
                                location(source_, lines_.number()), first_row));
      }
      file_.columns = detail::column_names(sections.titles(), count);
      file_.units = detail::column_units(sections.titles(), count);
    }
    file_.units.resize(file_.columns.size());
    units_from_header();
    const auto blocks = read_blocks(first_row);
    make_curves(blocks);
    check_counts(blocks);
    return std::move(file_);
  }

 private:
  // Field and moment units from "Units of measure" where no units line gave them.
  void units_from_header() {
    const auto system = file_.header_text("Units of measure").value_or("");
    const bool si = system.find("SI") != std::string::npos;
    const bool cgs =
        system.find("gs") != std::string::npos || system.find("GS") != std::string::npos;
    if (!si && !cgs) return;
    if (file_.units[0].empty()) file_.units[0] = si ? "T" : "Oe";
    if (file_.units[1].empty()) file_.units[1] = si ? "A m²" : "emu";
  }

  // Data blocks separated by blank lines, up to the end marker; `pending` is a row read ahead.
  std::vector<Block> read_blocks(std::string_view pending) {
    std::vector<Block> blocks;
    Block current;
    std::size_t points = 0;
    const auto close_block = [&] {
      if (current.size() == 0) return;
      blocks.push_back(std::move(current));
      current = Block{};
      if (blocks.size() > 2 * limits::kMaxForcCurves + 1) {
        throw Error(fmt::format("{}: more than {} FORCs; the limit is {} curves per file",
                                location(source_, lines_.number()), limits::kMaxForcCurves,
                                limits::kMaxForcCurves));
      }
    };
    std::string_view line;
    bool have_line = !pending.empty();
    if (have_line) line = pending;
    while (have_line || lines_.next(line)) {
      have_line = false;
      const auto content = trim(line);
      if (content.empty()) {
        close_block();
        continue;
      }
      if (detail::is_micromag_end_marker(content)) {
        close_block();
        return blocks;
      }
      if (++points > limits::kMaxForcPoints) {
        throw Error(fmt::format("{}: more than {} data points; the limit is {} per FORC file",
                                location(source_, lines_.number()), limits::kMaxForcPoints,
                                limits::kMaxForcPoints));
      }
      add_row(current, content);
    }
    throw Error(
        fmt::format("{}: the file ends without the line 'MicroMag 2900/3900 Data File "
                    "ends' (truncated?)",
                    location(source_, lines_.number())));
  }

  void add_row(Block& block, std::string_view content) {
    const auto count = file_.columns.size();
    if (block.columns.empty()) block.columns.resize(count);
    const auto fields = detail::split_fields(content, ',');
    if (file_.layout == MicromagForcLayout::series_0015) {
      const auto field = fields.size() == 2 ? parse_number(fields[0]) : std::nullopt;
      const auto moment = fields.size() == 2 ? parse_number(fields[1]) : std::nullopt;
      if (!field || !moment) {
        throw Error(fmt::format("{}: '{}' is not 'field,moment' with two finite numbers",
                                location(source_, lines_.number()), content));
      }
      block.columns[0].push_back(*field);
      block.columns[1].push_back(*moment);
    } else {
      if (fields.size() != count) {
        throw Error(
            fmt::format("{}: '{}' has {} comma-separated fields; the data rows have {} ({})",
                        location(source_, lines_.number()), content, fields.size(), count,
                        fmt::join(file_.columns, ", ")));
      }
      for (std::size_t j = 0; j < count; ++j) {
        const auto value = parse_number(fields[j]);
        if (!value) {
          throw Error(fmt::format("{}: column {} ('{}'): '{}' is not a finite number",
                                  location(source_, lines_.number()), j + 1, file_.columns[j],
                                  fields[j]));
        }
        block.columns[j].push_back(*value);
      }
    }
    block.lines.push_back(lines_.number());
  }

  // Rows [begin, end) of a block as a curve after the calibration row `calibration`.
  void add_curve(const Block& block, std::size_t calibration_row, const Block& calibration,
                 std::size_t begin) {
    MicromagForcFile::Curve curve;
    curve.calibration_field = calibration.columns[0][calibration_row];
    curve.calibration_moment = calibration.columns[1][calibration_row];
    curve.field.assign(block.columns[0].begin() + static_cast<std::ptrdiff_t>(begin),
                       block.columns[0].end());
    curve.moment.assign(block.columns[1].begin() + static_cast<std::ptrdiff_t>(begin),
                        block.columns[1].end());
    for (std::size_t j = 2; j < block.columns.size(); ++j) {
      curve.more_columns.emplace_back(block.columns[j].begin() + static_cast<std::ptrdiff_t>(begin),
                                      block.columns[j].end());
    }
    curve.first_line = block.lines[begin];
    file_.curves.push_back(std::move(curve));
  }

  // Blocks alternate: calibration point, curve, calibration point, curve, ...; a block whose
  // field falls after its first row holds its own calibration point (that first row).
  void make_curves(const std::vector<Block>& blocks) {
    const Block* calibration = nullptr;
    for (const auto& block : blocks) {
      if (calibration) {
        add_curve(block, 0, *calibration, 0);
        calibration = nullptr;
      } else if (block.size() == 1) {
        calibration = &block;
      } else if (block.columns[0][1] < block.columns[0][0]) {
        add_curve(block, 0, block, 1);
      } else {
        throw Error(fmt::format(
            "{}: a calibration block has {} points; expected 1 (blocks alternate: calibration "
            "point, FORC; or a FORC block opens with its calibration point, whose field is above "
            "the reversal field that follows)",
            location(source_, block.lines.front()), block.size()));
      }
    }
    if (calibration)
      file_.final_calibration = {calibration->columns[0][0], calibration->columns[1][0]};
    if (file_.curves.empty()) {
      throw Error(fmt::format("{}: the file has no FORC (only calibration points)",
                              location(source_, lines_.number())));
    }
  }

  void check_counts(const std::vector<Block>& blocks) const {
    std::size_t rows = 0;
    for (const auto& block : blocks)
      rows += block.size();
    if (file_.layout == MicromagForcLayout::series_0015) {
      if (const auto declared = file_.header_number("NData")) {
        if (*declared != static_cast<double>(rows)) {
          throw Error(fmt::format("{}: the header says NData = {} but the file has {} data points",
                                  location(source_, lines_.number()), *declared, rows));
        }
      }
      return;
    }
    // Whether "Number of data" counts the calibration points is not documented: either count is
    // accepted.
    if (const auto declared = file_.header_number("Number of data")) {
      if (*declared != static_cast<double>(rows) &&
          *declared != static_cast<double>(file_.points())) {
        throw Error(fmt::format(
            "{}: the header says 'Number of data {}' but the file has {} data rows ({} FORC "
            "points and {} calibration points)",
            location(source_, lines_.number()), *declared, rows, file_.points(),
            file_.calibration_points()));
      }
    }
  }

  detail::LineReader lines_;
  std::string_view source_;
  MicromagForcFile file_;
};

}  // namespace

std::optional<std::string> MicromagForcFile::header_text(std::string_view key) const {
  return detail::entry_text(header, key);
}

std::optional<double> MicromagForcFile::header_number(std::string_view key) const {
  return detail::entry_number(header, key);
}

std::size_t MicromagForcFile::points() const {
  std::size_t count = 0;
  for (const auto& curve : curves)
    count += curve.field.size();
  return count;
}

bool looks_like_micromag_forc(std::string_view text) {
  detail::LineReader lines(text);
  std::string_view first;
  std::string_view second;
  return lines.next(first) && detail::is_micromag_format_line(first) && lines.next(second) &&
         second.find("First-order reversal") != std::string_view::npos;
}

MicromagForcFile parse_micromag_forc(std::string_view text, std::string_view source_name) {
  check_text_encoding(text, source_name);
  return ForcParser(text, source_name).parse();
}

MicromagForcFile read_micromag_forc(const std::filesystem::path& path) {
  return parse_micromag_forc(read_file(path), path.string());
}

ForcDriftCorrection forc_drift_correction_from_string(std::string_view text) {
  return hyst::detail::value_named(text, enum_names<ForcDriftCorrection>, "FORC drift correction");
}

MicromagForcFile correct_drift(MicromagForcFile file, ForcDriftCorrection correction) {
  if (correction == ForcDriftCorrection::none || file.curves.empty()) return file;
  const double reference = file.curves.front().calibration_moment;
  const auto check = [&](double calibration, std::size_t curve) {
    if (correction == ForcDriftCorrection::multiplicative && calibration == 0.0) {
      throw Error(
          fmt::format("{}: calibration moment before curve {} is 0; multiplicative drift "
                      "correction needs it non-zero",
                      file.source, curve));
    }
  };
  for (std::size_t k = 0; k < file.curves.size(); ++k) {
    auto& curve = file.curves[k];
    const double before = curve.calibration_moment;
    const double after = k + 1 < file.curves.size() ? file.curves[k + 1].calibration_moment
                         : file.final_calibration   ? file.final_calibration->second
                                                    : before;
    check(before, k);
    check(after, k + 1);
    const auto n = static_cast<double>(curve.moment.size());
    for (std::size_t i = 0; i < curve.moment.size(); ++i) {
      const double f = (static_cast<double>(i) + 1.0) / (n + 1.0);
      const double drift = before + f * (after - before);
      double& m = curve.moment[i];
      m = correction == ForcDriftCorrection::multiplicative ? m * reference / drift
                                                            : m - (drift - reference);
    }
  }
  // The calibration moments themselves become the reference once corrected.
  for (auto& curve : file.curves)
    curve.calibration_moment = reference;
  if (file.final_calibration) file.final_calibration->second = reference;
  return file;
}

}  // namespace hyst::io
