// The demo behind `make demo`: runs each section of demo_sections.hpp, which writes its CSV
// files and PNG plots, and collects their Markdown into results.md.
//
// Usage: hyst_demo [--data DIR] [--out DIR]   (defaults ../shared/data and out/demo)

#include <exception>
#include <filesystem>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "demo_sections.hpp"
#include "hyst/io/atomic_file.hpp"

namespace {

namespace fs = std::filesystem;

int run(const fs::path& data_dir, const fs::path& folder) {
  fs::create_directories(folder);
  std::string markdown = "# hyst demo\n\n";
  markdown += piezo_section(data_dir, folder);
  markdown += actuator_section(HYST_EXAMPLE_CONFIG_DIR "/msma_assumed.json", folder);
  markdown += seed_comparison_section(folder);
  markdown += model_comparison_section(data_dir, folder);
  hyst::io::write_file_atomically(folder / "results.md", markdown);
  fmt::print("{}\nwrote {}\n", markdown, folder.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  fs::path data_dir = "../shared/data";
  fs::path folder = "out/demo";
  if (argc % 2 == 0) {
    fmt::print(stderr, "hyst_demo: '{}' needs a value (use --data DIR, --out DIR)\n",
               argv[argc - 1]);
    return 2;
  }
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string_view flag = argv[i];
    if (flag == "--data") {
      data_dir = argv[i + 1];
    } else if (flag == "--out") {
      folder = argv[i + 1];
    } else {
      fmt::print(stderr, "hyst_demo: unknown option '{}' (use --data DIR, --out DIR)\n", flag);
      return 2;
    }
  }
  try {
    return run(data_dir, folder);
  } catch (const std::exception& error) {
    fmt::print(stderr, "hyst_demo: error: {}\n", error.what());
    return 1;
  }
}
