#pragma once
/// The `language` benchmark of `simhuman eval`: a corpus of hand-written commands with their
/// expected plans (tests/data/language/corpus.jsonl, format in docs/FORMATS.md) run through a
/// planner. Reports exact-plan accuracy, the fraction of ambiguous commands refused with a
/// clarifying question, error-case accuracy and planning latency.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/language/planner.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::eval {

/// The corpus shipped with the sources.
std::string DefaultLanguageCorpusPath();

/// One corpus line.
struct LanguageCase {
  enum class Kind { kPlan, kAmbiguous, kError };
  int line = 0;         ///< 1-based line in the corpus file
  std::string scene;    ///< built-in name, or a JSON file relative to the corpus folder
  std::string command;  ///< the text
  Kind kind = Kind::kPlan;
  /// kPlan: steps, each a list of pair strings (see CompactStep()).
  std::vector<std::vector<std::string>> expect;
};

/// Reads a corpus (JSON lines). Errors name "<path>:<line>" and the bad key.
core::StatusOr<std::vector<LanguageCase>> LoadLanguageCorpus(const std::string& path);

/// One pair as "object|part|joint|contact|direction" ("object|none|none|none|side" for get
/// close, "object|part|@subject:subject_part|contact|direction" for object-object pairs).
std::string CompactPair(const plan::ContactPair& pair);
/// The pairs of a step in CompactPair() form, sorted (pair order within a step is free); a carry
/// step is the one string plan::CarrySummary() ("carry box000 by 0 to beside bed001").
std::vector<std::string> CompactStep(const plan::ContactStep& step);

/// The outcome of one case.
struct LanguageCaseResult {
  LanguageCase c;
  bool pass = false;
  std::string got;  ///< the plan in compact form, or "<code>: <message>"
  double latency_us = 0;
};

/// Aggregates over the corpus.
struct LanguageSummary {
  int cases = 0;
  int plan_cases = 0, plan_exact = 0;
  int ambiguous_cases = 0, ambiguous_refused = 0;
  int error_cases = 0, error_correct = 0;
  double median_latency_us = 0, p99_latency_us = 0, max_latency_us = 0;
  std::vector<LanguageCaseResult> results;

  double exact_rate() const { return plan_cases ? double(plan_exact) / plan_cases : 1.0; }
  double refused_rate() const {
    return ambiguous_cases ? double(ambiguous_refused) / ambiguous_cases : 1.0;
  }
  double error_rate() const { return error_cases ? double(error_correct) / error_cases : 1.0; }
};

/// Runs every case through `planner` (scenes are loaded once each; a scene that fails to load
/// is an error naming the corpus line). Latency is the wall time of Planner::Plan().
core::StatusOr<LanguageSummary> RunLanguageCorpus(const std::vector<LanguageCase>& cases,
                                                  const std::string& corpus_dir,
                                                  language::Planner& planner);

/// summary.json of the language suite: the counts, rates and latencies, then the failed cases.
nlohmann::ordered_json LanguageSummaryJson(const LanguageSummary& summary,
                                           const std::string& planner,
                                           const std::string& corpus_path);

}  // namespace simhuman::eval
