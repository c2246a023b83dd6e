// Fuzz target: the CSV reader (hyst::io::parse_csv). The first byte chooses the separator option,
// the rest is the file. Whatever parses must also survive format_csv -> parse_csv unchanged
// (17 significant digits round-trip every double), which checks the reader's numbers too.

#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_support.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static constexpr char kSeparators[] = {0, ',', ';', '\t', ' '};
  hyst::io::CsvReadOptions options;
  options.separator = kSeparators[data[0] % sizeof kSeparators];
  const auto text = hyst::fuzz::as_text(data + 1, size - 1);

  hyst::io::Table table;
  try {
    table = hyst::io::parse_csv(text, "fuzz.csv", options);
  } catch (const hyst::Error&) {
    return 0;  // rejected with a message: the expected outcome for most inputs
  }
  for (const auto& column : table.columns) {
    if (column.size() != table.rows()) std::abort();  // ragged table accepted
  }
  std::string written;
  try {
    written = hyst::io::format_csv(table);
  } catch (const hyst::Error&) {
    return 0;  // e.g. a table without rows, or names that the writer refuses
  }
  const auto again = hyst::io::parse_csv(written, "again.csv");
  if (again.names != table.names || again.columns != table.columns) std::abort();
  return 0;
}
