#include "data_source.hpp"

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::cli {

ColumnPair read_column_pair(const DataSource& source, std::string_view input,
                            std::string_view output, std::string_view what) {
  ColumnPair pair{source.column(input), source.column(output)};
  if (pair.input.size() != pair.output.size()) {
    throw Error(fmt::format("{} '{}': input '{}' has {} samples but output '{}' has {}", what,
                            source.path().string(), input, pair.input.size(), output,
                            pair.output.size()));
  }
  if (pair.input.empty()) {
    throw Error(
        fmt::format("{} '{}': input '{}' has no samples", what, source.path().string(), input));
  }
  return pair;
}

}  // namespace hyst::cli
