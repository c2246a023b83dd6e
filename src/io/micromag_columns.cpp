#include "micromag_columns.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "text_encoding.hpp"
#include "text_fields.hpp"

namespace hyst::io::detail {
namespace {

//! Words of a title line with the column of their centre.
struct Word {
  std::string_view text;
  double centre = 0.0;
};

std::vector<Word> words_of(std::string_view line) {
  std::vector<Word> words;
  std::size_t position = 0;
  while (true) {
    const auto start = line.find_first_not_of(kBlank, position);
    if (start == std::string_view::npos) return words;
    auto end = line.find_first_of(kBlank, start);
    if (end == std::string_view::npos) end = line.size();
    words.push_back({line.substr(start, end - start), 0.5 * static_cast<double>(start + end)});
    position = end;
  }
}

bool is_units_line(const std::vector<Word>& words) {
  return !words.empty() && words.front().text.starts_with('(');
}

}  // namespace

std::vector<std::string> column_names(const std::vector<std::string_view>& titles,
                                      std::size_t count) {
  // The line with one word per column gives the names, words of other lines ("Raw", "Adjusted")
  // are put before the name they stand over, and a units line ("(T)  (Am2)") is skipped.
  std::vector<std::vector<Word>> lines;
  for (const auto title : titles) {
    auto words = words_of(title);
    if (!is_units_line(words)) lines.push_back(std::move(words));
  }
  const auto name_line = std::find_if(lines.rbegin(), lines.rend(),
                                      [&](const auto& words) { return words.size() == count; });
  std::vector<std::string> names(count);
  if (name_line == lines.rend()) {
    for (std::size_t j = 0; j < count; ++j)
      names[j] = fmt::format("Column {}", j + 1);
    // Without any title line (the older exports: data right after the format and title lines)
    // the first two columns are the field and the moment, as in every MicroMag export.
    if (titles.empty() && count >= 2) {
      names[0] = "Field";
      names[1] = "Moment";
    }
    return names;
  }
  std::vector<std::string> qualifiers(count);
  for (const auto& words : lines) {
    if (&words == &*name_line) continue;
    for (const auto& word : words) {
      std::size_t nearest = 0;
      for (std::size_t j = 1; j < count; ++j) {
        if (std::abs((*name_line)[j].centre - word.centre) <
            std::abs((*name_line)[nearest].centre - word.centre)) {
          nearest = j;
        }
      }
      qualifiers[nearest] += std::string(word.text) + " ";
    }
  }
  for (std::size_t j = 0; j < count; ++j)
    names[j] = utf8_from_latin1(qualifiers[j] + std::string((*name_line)[j].text));
  // Repeated names (no qualifier line) get the column number.
  for (std::size_t j = 0; j < count; ++j) {
    if (std::count(names.begin(), names.end(), names[j]) > 1) {
      names[j] = fmt::format("{} (column {})", names[j], j + 1);
    }
  }
  return names;
}

std::vector<std::string> column_units(const std::vector<std::string_view>& titles,
                                      std::size_t count) {
  for (const auto title : titles) {
    const auto words = words_of(title);
    if (!is_units_line(words) || words.size() != count) continue;
    std::vector<std::string> units;
    for (const auto& word : words) {
      auto text = word.text;
      if (text.starts_with('(')) text.remove_prefix(1);
      if (text.ends_with(')')) text.remove_suffix(1);
      units.push_back(utf8_from_latin1(text));
    }
    return units;
  }
  return std::vector<std::string>(count);
}

}  // namespace hyst::io::detail
