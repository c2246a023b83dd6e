// The demo behind `make demo`: runs each section of demo_sections.hpp, which writes its CSV
// files and PNG plots, and collects their Markdown into results.md.
//
// Usage: hyst_demo [--data DIR] [--out DIR] [--only SECTION]
//   (defaults ../shared/data and out/demo; SECTION: piezo, actuator, seed, creep, hold or models)

#include <algorithm>
#include <exception>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "demo_sections.hpp"
#include "hyst/io/atomic_file.hpp"
#include "progress_display.hpp"

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kUsage = "use --data DIR, --out DIR, --only SECTION";

int run(const fs::path& data_dir, const fs::path& folder, std::string_view only) {
  const std::vector<std::pair<std::string_view, std::function<std::string()>>> sections{
      {"piezo", [&] { return piezo_section(data_dir, folder); }},
      {"actuator",
       [&] { return actuator_section(HYST_EXAMPLE_CONFIG_DIR "/msma_assumed.json", folder); }},
      {"seed", [&] { return seed_comparison_section(folder); }},
      {"creep", [&] { return creep_section(data_dir, folder); }},
      {"hold", [&] { return creep_hold_section(data_dir, folder); }},
      {"models", [&] { return model_comparison_section(data_dir, folder); }},
  };
  if (!only.empty() && std::none_of(sections.begin(), sections.end(),
                                    [&](const auto& section) { return section.first == only; })) {
    fmt::print(stderr,
               "hyst_demo: unknown section '{}' (piezo, actuator, seed, creep, hold, models)\n",
               only);
    return 2;
  }
  fs::create_directories(folder);
  std::string markdown = "# hyst demo\n\n";
  // Progress on standard error when it is a terminal (make demo run by hand).
  hyst::cli::ProgressDisplay display("hyst_demo", hyst::cli::ProgressMode::automatic);
  const auto progress = display.callback();
  const auto total = only.empty() ? sections.size() : 1;
  std::size_t done = 0;
  for (const auto& [name, section] : sections) {
    if (!only.empty() && name != only) continue;
    if (progress) progress({"sections", done, total, name});
    markdown += section();
    ++done;
  }
  if (progress) progress({"sections", done, total, {}});
  hyst::io::write_file_atomically(folder / "results.md", markdown);
  fmt::print("{}\nwrote {}\n", markdown, folder.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  fs::path data_dir = "../shared/data";
  fs::path folder = "out/demo";
  std::string only;
  if (argc % 2 == 0) {
    fmt::print(stderr, "hyst_demo: '{}' needs a value ({})\n", argv[argc - 1], kUsage);
    return 2;
  }
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string_view flag = argv[i];
    if (flag == "--data") {
      data_dir = argv[i + 1];
    } else if (flag == "--out") {
      folder = argv[i + 1];
    } else if (flag == "--only") {
      only = argv[i + 1];
    } else {
      fmt::print(stderr, "hyst_demo: unknown option '{}' ({})\n", flag, kUsage);
      return 2;
    }
  }
  try {
    return run(data_dir, folder, only);
  } catch (const std::exception& error) {
    fmt::print(stderr, "hyst_demo: error: {}\n", error.what());
    return 1;
  }
}
