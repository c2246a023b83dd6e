#include "hyst/io/micromag_forc.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "micromag_lines.hpp"
#include "text_encoding.hpp"
#include "text_fields.hpp"

namespace hyst::io {
namespace {

using detail::location;
using detail::parse_number;
using detail::trim;

struct Block {
  std::vector<double> field;
  std::vector<double> moment;
  std::size_t first_line = 0;
};

constexpr std::array<std::pair<ForcDriftCorrection, std::string_view>, 3> kDriftNames{{
    {ForcDriftCorrection::none, "none"},
    {ForcDriftCorrection::multiplicative, "multiplicative"},
    {ForcDriftCorrection::additive, "additive"},
}};

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

MicromagForcFile parse_micromag_forc(std::string_view text, std::string_view source_name) {
  check_text_encoding(text, source_name);
  MicromagForcFile file;
  file.source = std::string(source_name);
  std::size_t line_number = 0;
  std::size_t position = 0;
  const auto next_line = [&](std::string_view& line) {
    if (position >= text.size()) return false;
    const auto end = text.find('\n', position);
    line = text.substr(position,
                       end == std::string_view::npos ? text.size() - position : end - position);
    position = end == std::string_view::npos ? text.size() : end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++line_number;
    return true;
  };

  std::string_view line;
  if (!next_line(line) || !detail::is_micromag_format_line(line)) {
    throw Error(
        fmt::format("{}: not a MicroMag data file (the first line is '{}', expected "
                    "'MicroMag 2900/3900 Data File (Series ...)')",
                    location(source_name, 1), trim(line)));
  }
  file.format = std::string(trim(line));
  if (next_line(line)) file.title = std::string(trim(line));

  // Header: up to and including the NData line.
  bool header_done = false;
  while (!header_done && next_line(line)) {
    const auto content = trim(line);
    const auto split = content.find_first_of("=:");
    if (split == std::string_view::npos) continue;
    const auto key = trim(content.substr(0, split));
    const auto value = trim(content.substr(split + 1));
    if (key.empty()) continue;
    file.header.emplace_back(std::string(key), std::string(value));
    header_done = key == "NData";
  }
  if (!header_done) {
    throw Error(
        fmt::format("{}: no 'NData = ...' line: the header does not end, or this is not a "
                    "FORC file",
                    location(source_name, line_number)));
  }

  // Data blocks separated by blank lines, up to the end marker.
  std::vector<Block> blocks;
  Block current;
  bool ended = false;
  while (next_line(line)) {
    const auto content = trim(line);
    if (content.empty()) {
      if (!current.field.empty()) blocks.push_back(std::move(current));
      current = Block{};
      continue;
    }
    if (detail::is_micromag_end_marker(content)) {
      ended = true;
      break;
    }
    const auto comma = content.find(',');
    const auto field =
        comma == std::string_view::npos ? std::nullopt : parse_number(content.substr(0, comma));
    const auto moment =
        comma == std::string_view::npos ? std::nullopt : parse_number(content.substr(comma + 1));
    if (!field || !moment) {
      throw Error(fmt::format("{}: '{}' is not 'field,moment' with two finite numbers",
                              location(source_name, line_number), content));
    }
    if (current.field.empty()) current.first_line = line_number;
    current.field.push_back(*field);
    current.moment.push_back(*moment);
  }
  if (!current.field.empty()) blocks.push_back(std::move(current));
  if (!ended) {
    throw Error(
        fmt::format("{}: the file ends without the line 'MicroMag 2900/3900 Data File "
                    "ends' (truncated?)",
                    location(source_name, line_number)));
  }

  // Blocks alternate: calibration point, curve, calibration point, curve, ...
  std::size_t points = 0;
  for (std::size_t b = 0; b < blocks.size(); b += 2) {
    const Block& calibration = blocks[b];
    points += calibration.field.size();
    if (calibration.field.size() != 1) {
      throw Error(
          fmt::format("{}: a calibration block has {} points; expected 1 (blocks alternate: "
                      "calibration point, FORC)",
                      location(source_name, calibration.first_line), calibration.field.size()));
    }
    if (b + 1 == blocks.size()) {
      file.final_calibration = {calibration.field[0], calibration.moment[0]};
      break;
    }
    Block& curve = blocks[b + 1];
    points += curve.field.size();
    file.curves.push_back({calibration.field[0], calibration.moment[0], std::move(curve.field),
                           std::move(curve.moment), curve.first_line});
  }
  if (const auto declared = file.header_number("NData")) {
    if (*declared != static_cast<double>(points)) {
      throw Error(fmt::format("{}: the header says NData = {} but the file has {} data points",
                              location(source_name, line_number), *declared, points));
    }
  }
  if (file.curves.empty()) {
    throw Error(fmt::format("{}: the file has no FORC (only calibration points)",
                            location(source_name, line_number)));
  }
  return file;
}

MicromagForcFile read_micromag_forc(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw Error(fmt::format("cannot open MicroMag FORC file '{}'", path.string()));
  std::ostringstream content;
  content << stream.rdbuf();
  return parse_micromag_forc(content.str(), path.string());
}

std::string_view to_string(ForcDriftCorrection correction) {
  for (const auto& [value, name] : kDriftNames) {
    if (value == correction) return name;
  }
  return "unknown";
}

ForcDriftCorrection forc_drift_correction_from_string(std::string_view text) {
  for (const auto& [value, name] : kDriftNames) {
    if (name == text) return value;
  }
  throw Error(fmt::format(
      "unknown FORC drift correction '{}' (expected none, multiplicative or additive)", text));
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
