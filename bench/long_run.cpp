// Long runs: every registered model (its example parameters, through the registry's batch
// simulate, one call per period) over a periodic input for --samples samples. Checks that the
// output is periodic without drift - every period after the first equals the second one at the
// same phase within --tolerance (1e-12) - and that memory does not grow: the size of the model's
// state (the number of values in its state document; for the Preisach model the stored extrema)
// stays at its value after the first periods, and the process's peak resident memory stays put.
//
//     long_run [--samples 100000000] [--period 1000] [--tolerance 1e-12] [--model NAME]
//
// Prints one line per model; exit status 1 when a model drifts or its state grows.

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "hyst/models/preisach.hpp"
#include "hyst/registry/model_registry.hpp"

namespace {

struct Options {
  long long samples = 100'000'000;
  std::size_t period = 1000;
  double tolerance = 1e-12;
  std::string model;  // empty: every model
};

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string name = argv[i];
    const char* value = argv[i + 1];
    if (name == "--samples") {
      options.samples = static_cast<long long>(std::strtod(value, nullptr));
    } else if (name == "--period") {
      options.period = static_cast<std::size_t>(std::strtoull(value, nullptr, 10));
    } else if (name == "--tolerance") {
      options.tolerance = std::strtod(value, nullptr);
    } else if (name == "--model") {
      options.model = value;
    } else {
      std::fprintf(stderr, "long_run: unknown option '%s'\n", argv[i]);
      std::exit(2);
    }
  }
  if (argc % 2 == 0 || options.samples <= 0 || options.period < 4) {
    std::fprintf(stderr,
                 "usage: long_run [--samples N] [--period P>=4] [--tolerance T] [--model NAME]\n");
    std::exit(2);
  }
  return options;
}

//! One period of a signal with a major loop and two nested minor loops inside [-0.9, 0.9]: the
//! same samples every period, bit for bit.
std::vector<double> periodic_input(std::size_t period) {
  std::vector<double> input(period);
  for (std::size_t k = 0; k < period; ++k) {
    const double phase =
        2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(period);
    input[k] = 0.6 * std::sin(phase) + 0.3 * std::sin(3.0 * phase);
  }
  return input;
}

//! Local extrema of one period, seen as a cycle: a bound for the memory a Preisach model needs.
std::size_t extrema_per_period(const std::vector<double>& input) {
  std::size_t count = 0;
  const std::size_t n = input.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double before = input[(k + n - 1) % n], here = input[k], after = input[(k + 1) % n];
    if ((here > before && here >= after) || (here < before && here <= after)) ++count;
  }
  return count;
}

//! Number of numbers in a JSON document (arrays and objects counted through).
std::size_t value_count(const nlohmann::json& json) {
  if (json.is_array() || json.is_object()) {
    std::size_t count = 0;
    for (const auto& item : json)
      count += value_count(item);
    return count;
  }
  return json.is_number() ? 1 : 0;
}

long peak_resident_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

bool run_model(const hyst::ModelEntry& entry, const Options& options) {
  auto model = entry.create(entry.example_params, nullptr);
  const auto input = periodic_input(options.period);
  std::vector<double> output(options.period), reference(options.period), previous(options.period);

  const long long periods = std::max(3LL, options.samples / static_cast<long long>(options.period));
  double max_deviation = 0.0;
  double last_change = 0.0;  // max |y - y(one period earlier)| over the last period
  long long identical_periods = 0;
  std::size_t state_size_after_warmup = 0, state_size_max = 0;
  long rss_after_warmup = 0;
  const auto start = std::chrono::steady_clock::now();
  for (long long p = 0; p < periods; ++p) {
    model->simulate(input, output);
    if (p == 1) {
      reference = output;
      state_size_after_warmup = value_count(model->state());
      rss_after_warmup = peak_resident_kb();
    } else if (p > 1) {
      double deviation = 0.0;
      last_change = 0.0;
      for (std::size_t k = 0; k < options.period; ++k) {
        deviation = std::max(deviation, std::abs(output[k] - reference[k]));
        last_change = std::max(last_change, std::abs(output[k] - previous[k]));
      }
      max_deviation = std::max(max_deviation, deviation);
      if (std::memcmp(output.data(), reference.data(), output.size() * sizeof(double)) == 0) {
        ++identical_periods;
      }
      // The state document is built only now and then: it allocates, the simulation does not.
      if (p % 1024 == 0 || p == periods - 1) {
        state_size_max = std::max(state_size_max, value_count(model->state()));
      }
    }
    std::swap(previous, output);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long long samples = periods * static_cast<long long>(options.period);
  const long rss_end = peak_resident_kb();

  // Models with wiping-out memory (play, relay, Preisach) repeat from the second period on; the
  // differential models (Bouc-Wen, Duhem, Jiles-Atherton, ...) approach their periodic orbit
  // exponentially, so for them no drift means that the last period repeats the one before.
  const bool periodic_from_period_2 = max_deviation <= options.tolerance;
  const bool converged = last_change <= options.tolerance;
  const bool drift = !periodic_from_period_2 && !converged;
  const bool grows = state_size_max > state_size_after_warmup || rss_end > rss_after_warmup + 1024;
  fmt::print(
      "{:<10} samples {:>11}  {:6.2f} s  {:6.1f} ns/sample  max |y - y(period 2)| = {:.3g}  "
      "last period change {:.3g}  bit-identical periods {}/{}  state values {} -> max {} "
      "(extrema per period {})  peak RSS {} -> {} kB  {}\n",
      entry.name, samples, seconds, 1e9 * seconds / static_cast<double>(samples), max_deviation,
      last_change, identical_periods, periods - 2, state_size_after_warmup, state_size_max,
      extrema_per_period(input), rss_after_warmup, rss_end,
      drift ? "DRIFT" : (grows ? "GROWS" : (periodic_from_period_2 ? "ok" : "ok (converged)")));
  std::fflush(stdout);
  return !drift && !grows;
}

//! The Preisach model in its fast form as C++ (101 levels, uneven weights), stepped sample by
//! sample so that the size of its memory of extrema is seen after every sample.
bool run_preisach_memory(const Options& options) {
  std::vector<double> weights(hyst::preisach_relay_count(101));
  for (std::size_t k = 0; k < weights.size(); ++k)
    weights[k] = 1.0 + 0.5 * std::sin(0.37 * static_cast<double>(k));
  const hyst::Preisach model(
      {.everett = {.levels = 101, .lower = -1, .upper = 1, .weights = weights}});
  const auto input = periodic_input(options.period);
  auto state = model.initial_state();
  std::vector<double> reference(options.period);
  const long long periods = std::max(3LL, options.samples / static_cast<long long>(options.period));
  double max_deviation = 0.0;
  std::size_t memory_max = 0;
  const auto start = std::chrono::steady_clock::now();
  for (long long p = 0; p < periods; ++p) {
    for (std::size_t k = 0; k < options.period; ++k) {
      const double y = model.step(state, input[k]);
      memory_max = std::max(memory_max, state.size);
      if (p == 1) reference[k] = y;
      if (p > 1) max_deviation = std::max(max_deviation, std::abs(y - reference[k]));
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long long samples = periods * static_cast<long long>(options.period);
  // The memory holds x_0 and at most one entry per distinct extremum of the periodic input.
  const std::size_t bound = 1 + extrema_per_period(input);
  const bool drift = !(max_deviation <= options.tolerance);
  const bool grows = memory_max > bound || state.truncations != 0;
  fmt::print(
      "{:<10} samples {:>11}  {:6.2f} s  {:6.1f} ns/sample  max |y - y(period 2)| = {:.3g}  "
      "memory entries max {} (bound 1 + {} extrema per period), truncations {}  {}\n",
      "preisach (C++ fast form, 101 levels, step loop)", samples, seconds,
      1e9 * seconds / static_cast<double>(samples), max_deviation, memory_max, bound - 1,
      state.truncations, drift ? "DRIFT" : (grows ? "GROWS" : "ok"));
  return !drift && !grows;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  bool all_ok = true;
  for (const auto& entry : hyst::ModelRegistry::builtin().entries()) {
    if (!options.model.empty() && entry.name != options.model) continue;
    all_ok = run_model(entry, options) && all_ok;
  }
  if (options.model.empty() || options.model == "preisach") {
    all_ok = run_preisach_memory(options) && all_ok;
  }
  return all_ok ? 0 : 1;
}
