// fmu_run FMU CSV COLUMN [STEP]: drives an FMI 2.0 co-simulation FMU with one column of a CSV
// file (1-based, header line skipped) as its input (set, get, step by STEP, default 1e-3) and
// prints its output, one value per line with %.17g after the header "y". For the CLI tests.

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>

#include "fmu_host.hpp"

int main(int argc, char** argv) {
  if (argc < 4 || argc > 5) {
    std::fprintf(stderr, "usage: fmu_run FMU CSV COLUMN [STEP]\n");
    return 2;
  }
  try {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("fmu-run-" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    int status = 0;
    {
      const hyst::test::Fmu fmu(argv[1], folder);
      for (const auto& problem : fmu.description_problems()) {
        std::fprintf(stderr, "modelDescription.xml: %s\n", problem.c_str());
        status = 1;
      }
      hyst::test::FmuInstance instance(fmu);
      const int column = std::atoi(argv[3]);
      const double step = argc == 5 ? std::atof(argv[4]) : 1e-3;
      std::ifstream csv(argv[2]);
      std::string line;
      std::getline(csv, line);
      std::printf("y\n");
      while (std::getline(csv, line)) {
        std::istringstream fields(line);
        std::string field;
        for (int k = 0; k < column; ++k)
          std::getline(fields, field, ',');
        std::printf("%.17g\n", instance.sample(std::strtod(field.c_str(), nullptr), step));
      }
    }
    std::filesystem::remove_all(folder);
    return status;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "fmu_run: %s\n", error.what());
    return 1;
  }
}
