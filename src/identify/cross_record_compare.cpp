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
#include "hyst/identify/reference_predictors.hpp"
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

// The fit records of a round joined one after the other.
struct JoinedRecords {
  std::vector<double> input;
  std::vector<double> output;
};

JoinedRecords joined(const FitRound& round) {
  JoinedRecords records;
  for (const auto* record : round.fit) {
    records.input.insert(records.input.end(), record->input.begin(), record->input.end());
    records.output.insert(records.output.end(), record->output.begin(), record->output.end());
  }
  return records;
}

void run_round(const ModelEntry& entry, const FitRound& round, const CrossRecordOptions& options,
               CrossRecordRow& row) {
  const auto fit = joined(round);
  FitRequest request;
  request.input = fit.input;
  request.output = fit.output;
  if (const auto found = options.fit_options.find(entry.name); found != options.fit_options.end()) {
    request.options = found->second;
  }
  request.options = with_sample_time(entry, std::move(request.options), options.sample_time);
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
    auto metrics = validate_on_record(*outcome.model, fit.input, record->input, record->output,
                                      options.validation);
    if (!std::isfinite(metrics.nrmse_percent)) {
      throw Error(fmt::format("unstable: the prediction of '{}' is not finite", record->name));
    }
    HeldOutScore score{record->name, names_of(round.fit), metrics, {}};
    if (outcome.report.domain) {
      score.domain =
          check_record_inputs(*outcome.report.domain, record->input, options.sample_time);
    }
    row.scores.push_back(std::move(score));
  }
}

// Mean and worst NRMSE of `scores`, for a model row or a reference.
template <class Row>
void summarise(Row& row) {
  double sum = 0.0;
  for (const auto& score : row.scores) {
    sum += score.metrics.nrmse_percent;
    if (score.metrics.nrmse_percent >= row.worst_nrmse_percent) {
      row.worst_nrmse_percent = score.metrics.nrmse_percent;
      row.worst_record = score.record;
    }
  }
  row.mean_nrmse_percent = sum / static_cast<double>(row.scores.size());
}

// The reference predictors of every round, one CrossRecordReference per predictor.
std::vector<CrossRecordReference> yardstick(const std::vector<FitRound>& rounds,
                                            const CrossRecordOptions& options) {
  ReferenceOptions reference;
  reference.time_series =
      options.time_series && options.validation.start == ValidationStart::continued;
  reference.align_first_sample = options.validation.align == ValidationAlignment::first_sample;
  std::vector<CrossRecordReference> references;
  for (const auto& round : rounds) {
    const auto fit = joined(round);
    for (const auto* record : round.held_out) {
      const auto scores = reference_predictions_on_record(fit.input, fit.output, record->input,
                                                          record->output, reference);
      if (references.empty()) {
        for (const auto& score : scores) {
          CrossRecordReference row;
          row.name = score.name;
          row.ok = true;
          references.push_back(std::move(row));
        }
      }
      for (std::size_t i = 0; i < scores.size(); ++i) {
        auto& row = references[i];
        if (!row.ok) continue;
        if (!scores[i].validation) {
          row.ok = false;
          row.error = fmt::format("on '{}': {}", record->name, scores[i].error);
          row.scores.clear();
          continue;
        }
        row.scores.push_back({record->name, names_of(round.fit), *scores[i].validation, {}});
      }
    }
  }
  for (auto& row : references) {
    if (row.ok) summarise(row);
  }
  return references;
}

// The held-out records on which even the best model exceeds the threshold, with what they show.
std::vector<NoFitVerdict> no_fit_verdicts(const std::vector<FitRound>& rounds,
                                          const std::vector<CrossRecordRow>& ranking,
                                          double threshold) {
  std::vector<NoFitVerdict> verdicts;
  std::size_t index = 0;  // of the held-out record in the rows' scores
  for (const auto& round : rounds) {
    const auto fit = joined(round);
    for (const auto* record : round.held_out) {
      const CrossRecordRow* best = nullptr;
      for (const auto& row : ranking) {
        if (row.ok && (best == nullptr || row.scores[index].metrics.nrmse_percent <
                                              best->scores[index].metrics.nrmse_percent)) {
          best = &row;
        }
      }
      if (best != nullptr && best->scores[index].metrics.nrmse_percent > threshold) {
        verdicts.push_back({record->name, best->model, best->scores[index].metrics.nrmse_percent,
                            diagnose_held_out_record(fit.input, record->input, record->output)});
      }
      ++index;
    }
  }
  return verdicts;
}

CrossRecordRow compare_one(const ModelEntry& entry, const std::vector<FitRound>& rounds,
                           const CrossRecordOptions& options) {
  CrossRecordRow row;
  row.model = entry.name;
  try {
    for (const auto& round : rounds)
      run_round(entry, round, options, row);
    summarise(row);
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
  if (!(options.no_fit_percent > 0.0) || !std::isfinite(options.no_fit_percent)) {
    throw Error(
        fmt::format("compare: no_fit_percent = {} must be finite and > 0", options.no_fit_percent),
        "no_fit_percent");
  }
  const auto entries = compared_models(options.models, options.fit_options, registry);
  CrossRecordComparison comparison;
  comparison.rule = describe(options.validation);
  for (const auto& round : rounds) {
    for (const auto& name : names_of(round.held_out))
      comparison.validate_records.push_back(name);
  }
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (options.progress) options.progress({"models", k, entries.size(), entries[k]->name});
    comparison.ranking.push_back(compare_one(*entries[k], rounds, options));
  }
  if (options.progress) options.progress({"models", entries.size(), entries.size(), {}});
  std::stable_sort(comparison.ranking.begin(), comparison.ranking.end(),
                   [](const CrossRecordRow& a, const CrossRecordRow& b) {
                     if (a.ok != b.ok) return a.ok;
                     return a.ok && a.mean_nrmse_percent < b.mean_nrmse_percent;
                   });
  comparison.references = yardstick(rounds, options);
  const auto* best = best_cross_record_reference(comparison);
  for (auto& row : comparison.ranking) {
    row.beats_yardstick =
        row.ok && (best == nullptr || row.mean_nrmse_percent < best->mean_nrmse_percent);
  }
  comparison.no_fit_percent = options.no_fit_percent;
  comparison.no_fit = no_fit_verdicts(rounds, comparison.ranking, options.no_fit_percent);
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

const CrossRecordReference* best_cross_record_reference(const CrossRecordComparison& comparison) {
  const CrossRecordReference* best = nullptr;
  for (const auto& reference : comparison.references) {
    if (reference.ok &&
        (best == nullptr || reference.mean_nrmse_percent < best->mean_nrmse_percent))
      best = &reference;
  }
  return best;
}

namespace {

using detail::yes_no;

std::string no_fit_lines(const CrossRecordComparison& comparison) {
  std::string text;
  for (const auto& verdict : comparison.no_fit) {
    std::string seen;
    for (const auto& finding : verdict.seen.findings)
      seen += (seen.empty() ? "" : "; ") + finding;
    text += fmt::format(
        "No model describes the record {}: the best held-out NRMSE on it is {:.4g} % ({}), above "
        "{:g} %. {}\n\n",
        verdict.record, verdict.best_nrmse_percent, verdict.best_model, comparison.no_fit_percent,
        seen.empty() ? std::string("None of the looks at the record (butterfly, drift, "
                                   "extrapolation) finds the cause.")
                     : fmt::format("Seen: {}.", seen));
  }
  return text;
}

std::string yardstick_line(const CrossRecordComparison& comparison) {
  const auto* best = best_cross_record_reference(comparison);
  if (best == nullptr) return "Yardstick: no reference predictor could be made on these records.";
  std::string scores;
  for (const auto& reference : comparison.references) {
    if (!scores.empty()) scores += ", ";
    scores += reference.ok
                  ? fmt::format("{} {:.4g} %", reference.name, reference.mean_nrmse_percent)
                  : fmt::format("{} not made ({})", reference.name, reference.error);
  }
  std::string losers;
  for (const auto& row : comparison.ranking) {
    if (row.ok && !row.beats_yardstick) losers += (losers.empty() ? "" : ", ") + row.model;
  }
  return fmt::format(
      "Yardstick (reference predictors fitted on the same fit records, mean NRMSE over the "
      "held-out records): {}. Best reference: {}, mean NRMSE {:.4g} %. {}",
      scores, best->name, best->mean_nrmse_percent,
      losers.empty() ? std::string("Every fitted model beats it.")
                     : fmt::format("Models that do not beat it: {}.", losers));
}

}  // namespace

std::string held_out_domain_lines(const CrossRecordComparison& comparison) {
  std::string text;
  for (const auto& record : comparison.validate_records) {
    std::vector<std::pair<std::string, DomainCheck>> checks;
    std::size_t samples = 0;
    for (const auto& row : comparison.ranking) {
      if (!row.ok) continue;
      for (const auto& score : row.scores) {
        if (score.record != record) continue;
        checks.emplace_back(row.model, score.domain);
        samples = score.metrics.samples;
      }
    }
    if (const auto message = models_domain_message(checks, samples); !message.empty()) {
      text += fmt::format(
          "Held-out record '{}' leaves the domain the models were fitted on (their scores there "
          "measure extrapolation): {}.\n\n",
          record, message);
    }
  }
  return text;
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
  text += no_fit_lines(comparison);
  text += yardstick_line(comparison) + "\n\n";
  text += held_out_domain_lines(comparison);
  text +=
      "| rank | model | mean held-out NRMSE [%] | worst held-out NRMSE [%] | worst record | beats "
      "yardstick |";
  std::string rule = "|---:|---|---:|---:|---|---|";
  for (const auto& record : comparison.validate_records) {
    text += fmt::format(" {} [%] |", detail::markdown_cell(record));
    rule += "---:|";
  }
  text += " parameters | fit time [s] | status |\n" + rule + "---:|---:|---|\n";
  const auto dashes = [&] {
    std::string cells;
    for (std::size_t i = 0; i < comparison.validate_records.size(); ++i)
      cells += " - |";
    return cells;
  };
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      text += fmt::format("| {} | {} | {:.4g} | {:.4g} | {} | {} |", ++rank, row.model,
                          row.mean_nrmse_percent, row.worst_nrmse_percent,
                          detail::markdown_cell(row.worst_record), yes_no(row.beats_yardstick));
      for (const auto& score : row.scores)
        text += fmt::format(" {:.4g} |", score.metrics.nrmse_percent);
      text += fmt::format(" {} | {:.3g} | {} |\n", row.parameters, row.fit_seconds, row.status);
    } else {
      text += fmt::format("| - | {} | - | - | - | - |{} - | - | failed: {} |\n", row.model,
                          dashes(), detail::markdown_cell(row.error));
    }
  }
  for (const auto& reference : comparison.references) {
    if (reference.ok) {
      text += fmt::format("| ref | reference: {} | {:.4g} | {:.4g} | {} | - |", reference.name,
                          reference.mean_nrmse_percent, reference.worst_nrmse_percent,
                          detail::markdown_cell(reference.worst_record));
      for (const auto& score : reference.scores)
        text += fmt::format(" {:.4g} |", score.metrics.nrmse_percent);
      text += " - | - | reference |\n";
    } else {
      text += fmt::format("| ref | reference: {} | - | - | - | - |{} - | - | not made: {} |\n",
                          reference.name, dashes(), detail::markdown_cell(reference.error));
    }
  }
  return text;
}

std::string cross_record_csv(const CrossRecordComparison& comparison) {
  std::string text =
      "rank,model,status,mean_nrmse_percent,worst_nrmse_percent,worst_record,parameters,"
      "fit_seconds,beats_yardstick";
  for (const auto& record : comparison.validate_records)
    text += "," + detail::csv_quoted("nrmse_percent:" + record);
  text += ",message\n";
  const std::string empty_scores(comparison.validate_records.size(), ',');
  std::size_t rank = 0;
  for (const auto& row : comparison.ranking) {
    if (row.ok) {
      text += fmt::format("{},{},{},{:.8g},{:.8g},{},{},{:.6g},{}", ++rank, row.model, row.status,
                          row.mean_nrmse_percent, row.worst_nrmse_percent,
                          detail::csv_quoted(row.worst_record), row.parameters, row.fit_seconds,
                          yes_no(row.beats_yardstick));
      for (const auto& score : row.scores)
        text += fmt::format(",{:.8g}", score.metrics.nrmse_percent);
      text += ",\"\"\n";
    } else {
      text += fmt::format("-,{},failed,,,,,,{},{}\n", row.model, empty_scores,
                          detail::csv_quoted(row.error));
    }
  }
  for (const auto& reference : comparison.references) {
    const auto name = detail::csv_quoted("reference: " + reference.name);
    if (reference.ok) {
      text += fmt::format("reference,{},reference,{:.8g},{:.8g},{},,,", name,
                          reference.mean_nrmse_percent, reference.worst_nrmse_percent,
                          detail::csv_quoted(reference.worst_record));
      for (const auto& score : reference.scores)
        text += fmt::format(",{:.8g}", score.metrics.nrmse_percent);
      text += ",\"\"\n";
    } else {
      text += fmt::format("reference,{},failed,,,,,,{},{}\n", name, empty_scores,
                          detail::csv_quoted(reference.error));
    }
  }
  return text;
}

}  // namespace hyst
