#include "hyst/identify/cross_record_compare.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <set>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/core/error.hpp"
#include "hyst/identify/compare.hpp"
#include "table_cells.hpp"

namespace hyst {
namespace {

using Clock = std::chrono::steady_clock;

void check_records(const std::vector<NamedRecord>& records, std::string_view role,
                   std::set<std::string>& names) {
  for (const auto& record : records) {
    if (record.input.size() != record.output.size()) {
      throw Error(fmt::format("compare: {} record '{}': input has {} samples, output {}", role,
                              record.name, record.input.size(), record.output.size()),
                  "records");
    }
    if (record.input.size() < 2) {
      throw Error(fmt::format("compare: {} record '{}' has {} samples; at least 2 are needed", role,
                              record.name, record.input.size()),
                  "records");
    }
    if (!names.insert(record.name).second) {
      throw Error(fmt::format("compare: record '{}' is given twice", record.name), "records");
    }
  }
}

// One fit on the joined fit records and the score on each held-out record.
struct FitRound {
  std::vector<const NamedRecord*> fit;
  std::vector<const NamedRecord*> held_out;
};

std::vector<std::string> names_of(const std::vector<const NamedRecord*>& records) {
  std::vector<std::string> names;
  for (const auto* record : records)
    names.push_back(record->name);
  return names;
}

void run_round(const ModelEntry& entry, const FitRound& round, const CrossRecordOptions& options,
               CrossRecordRow& row) {
  std::vector<double> input;
  std::vector<double> output;
  for (const auto* record : round.fit) {
    input.insert(input.end(), record->input.begin(), record->input.end());
    output.insert(output.end(), record->output.begin(), record->output.end());
  }
  FitRequest request;
  request.input = input;
  request.output = output;
  if (const auto found = options.fit_options.find(entry.name); found != options.fit_options.end()) {
    request.options = found->second;
  }
  const auto started = Clock::now();
  const auto outcome = fit_model(entry, request);
  row.fit_seconds += std::chrono::duration<double>(Clock::now() - started).count();
  if (!outcome.model || outcome.report.termination == Termination::failed) {
    throw Error(fmt::format("the fit on {} failed: {}", fmt::join(names_of(round.fit), ", "),
                            outcome.report.message));
  }
  row.parameters = outcome.model->parameter_count();
  row.status = std::string(outcome.report.status());
  for (const auto* record : round.held_out) {
    auto metrics = validate_on_record(*outcome.model, input, record->input, record->output,
                                      options.validation);
    if (!std::isfinite(metrics.nrmse_percent)) {
      throw Error(fmt::format("unstable: the prediction of '{}' is not finite", record->name));
    }
    row.scores.push_back({record->name, names_of(round.fit), metrics});
  }
}

CrossRecordRow compare_one(const ModelEntry& entry, const std::vector<FitRound>& rounds,
                           const CrossRecordOptions& options) {
  CrossRecordRow row;
  row.model = entry.name;
  try {
    for (const auto& round : rounds)
      run_round(entry, round, options, row);
    double sum = 0.0;
    for (const auto& score : row.scores) {
      sum += score.metrics.nrmse_percent;
      if (score.metrics.nrmse_percent >= row.worst_nrmse_percent) {
        row.worst_nrmse_percent = score.metrics.nrmse_percent;
        row.worst_record = score.record;
      }
    }
    row.mean_nrmse_percent = sum / static_cast<double>(row.scores.size());
    row.ok = true;
  } catch (const std::exception& error) {
    row.ok = false;
    row.error = error.what();
    row.scores.clear();
  }
  return row;
}

CrossRecordComparison run_rounds(const std::vector<FitRound>& rounds,
                                 const CrossRecordOptions& options, const ModelRegistry& registry) {
  const auto entries = compared_models(options.models, options.fit_options, registry);
  CrossRecordComparison comparison;
  comparison.rule = describe(options.validation);
  for (const auto& round : rounds) {
    for (const auto& name : names_of(round.held_out))
      comparison.validate_records.push_back(name);
  }
  for (const auto* entry : entries)
    comparison.ranking.push_back(compare_one(*entry, rounds, options));
  std::stable_sort(comparison.ranking.begin(), comparison.ranking.end(),
                   [](const CrossRecordRow& a, const CrossRecordRow& b) {
                     if (a.ok != b.ok) return a.ok;
                     return a.ok && a.mean_nrmse_percent < b.mean_nrmse_percent;
                   });
  return comparison;
}

std::vector<const NamedRecord*> pointers(const std::vector<NamedRecord>& records) {
  std::vector<const NamedRecord*> out;
  for (const auto& record : records)
    out.push_back(&record);
  return out;
}

}  // namespace

CrossRecordComparison compare_across_records(const std::vector<NamedRecord>& fit,
                                             const std::vector<NamedRecord>& validate,
                                             const CrossRecordOptions& options,
                                             const ModelRegistry& registry) {
  if (fit.empty()) throw Error("compare: no fit record given", "fit_records");
  if (validate.empty()) throw Error("compare: no held-out record given", "validate_records");
  std::set<std::string> names;
  check_records(fit, "fit", names);
  check_records(validate, "held-out", names);
  auto comparison = run_rounds({{pointers(fit), pointers(validate)}}, options, registry);
  comparison.fit_records = names_of(pointers(fit));
  return comparison;
}

CrossRecordComparison compare_leave_one_out(const std::vector<NamedRecord>& records,
                                            const CrossRecordOptions& options,
                                            const ModelRegistry& registry) {
  if (records.size() < 2) {
    throw Error(
        fmt::format("compare: leave-one-out needs at least 2 records, got {}", records.size()),
        "records");
  }
  std::set<std::string> names;
  check_records(records, "the", names);
  std::vector<FitRound> rounds;
  for (std::size_t held = 0; held < records.size(); ++held) {
    FitRound round;
    for (std::size_t i = 0; i < records.size(); ++i) {
      (i == held ? round.held_out : round.fit).push_back(&records[i]);
    }
    rounds.push_back(std::move(round));
  }
  auto comparison = run_rounds(rounds, options, registry);
  comparison.leave_one_out = true;
  return comparison;
}

std::string cross_record_markdown(const CrossRecordComparison& comparison) {
  std::string text =
      comparison.leave_one_out
          ? fmt::format(
                "Leave-one-out over the records {}: each held out in turn, every model "
                "fitted on the others joined in this order (the state runs on across "
                "each junction).\n\n",
                fmt::join(comparison.validate_records, ", "))
          : fmt::format(
                "Fitted on the records {} (joined in this order; the state runs on "
                "across each junction), ranked on the separate records {}.\n\n",
                fmt::join(comparison.fit_records, ", "),
                fmt::join(comparison.validate_records, ", "));
  text += fmt::format("Held-out records: {}.\n\n", comparison.rule);
  text += "| rank | model | mean held-out NRMSE [%] | worst held-out NRMSE [%] | worst record |";
  std::string rule = "|---:|---|---:|---:|---|";
  for (const auto& record : comparison.validate_records) {
    text += fmt::format(" {} [%] |", detail::markdown_cell(record));
    rule += "---:|";
  }
  text += " parameters | fit time [s] | status |\n" + rule + "---:|---:|---|\n";
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      text += fmt::format("| {} | {} | {:.4g} | {:.4g} | {} |", ++rank, row.model,
                          row.mean_nrmse_percent, row.worst_nrmse_percent,
                          detail::markdown_cell(row.worst_record));
      for (const auto& score : row.scores)
        text += fmt::format(" {:.4g} |", score.metrics.nrmse_percent);
      text += fmt::format(" {} | {:.3g} | {} |\n", row.parameters, row.fit_seconds, row.status);
    } else {
      text += fmt::format("| - | {} | - | - | - |", row.model);
      for (std::size_t i = 0; i < comparison.validate_records.size(); ++i)
        text += " - |";
      text += fmt::format(" - | - | failed: {} |\n", detail::markdown_cell(row.error));
    }
  }
  return text;
}

std::string cross_record_csv(const CrossRecordComparison& comparison) {
  std::string text =
      "rank,model,status,mean_nrmse_percent,worst_nrmse_percent,worst_record,parameters,"
      "fit_seconds";
  for (const auto& record : comparison.validate_records)
    text += "," + detail::csv_quoted("nrmse_percent:" + record);
  text += ",message\n";
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      text += fmt::format("{},{},{},{:.8g},{:.8g},{},{},{:.6g}", ++rank, row.model, row.status,
                          row.mean_nrmse_percent, row.worst_nrmse_percent,
                          detail::csv_quoted(row.worst_record), row.parameters, row.fit_seconds);
      for (const auto& score : row.scores)
        text += fmt::format(",{:.8g}", score.metrics.nrmse_percent);
      text += ",\"\"\n";
    } else {
      text += fmt::format("-,{},failed,,,,,", row.model);
      for (std::size_t i = 0; i < comparison.validate_records.size(); ++i)
        text += ",";
      text += "," + detail::csv_quoted(row.error) + "\n";
    }
  }
  return text;
}

}  // namespace hyst
