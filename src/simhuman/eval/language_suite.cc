#include "simhuman/eval/language_suite.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "simhuman/core/json_io.h"
#include "simhuman/core/version.h"
#include "simhuman/world/scene.h"

namespace simhuman::eval {
namespace {

struct LoadedScene {
  world::SceneSpec spec;
  core::SceneCatalog catalog;
};

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())));
  return v[k];
}

std::string CodeName(const absl::Status& s) { return absl::StatusCodeToString(s.code()); }

}  // namespace

std::string DefaultLanguageCorpusPath() {
  return std::string(SIMHUMAN_SOURCE_DIR) + "/tests/data/language/corpus.jsonl";
}

core::StatusOr<std::vector<LanguageCase>> LoadLanguageCorpus(const std::string& path) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError(path + ": cannot open the language corpus");
  std::vector<LanguageCase> out;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = path + ":" + std::to_string(line);
    SH_ASSIGN_OR_RETURN(nlohmann::json j, core::ParseJson(text, where));
    SH_RETURN_IF_ERROR(core::Annotate(
        core::CheckKeys(j, {"scene", "command", "expect", "expect_ambiguous", "expect_error"},
                        "(root)"),
        where));
    LanguageCase c;
    c.line = line;
    core::StatusOr<std::string> scene = core::GetString(j, "scene", "");
    if (!scene.ok()) return core::Annotate(scene.status(), where);
    core::StatusOr<std::string> command = core::GetString(j, "command", "");
    if (!command.ok()) return core::Annotate(command.status(), where);
    c.scene = *scene;
    c.command = *command;
    const int kinds =
        j.contains("expect") + j.contains("expect_ambiguous") + j.contains("expect_error");
    if (kinds != 1) {
      return absl::InvalidArgumentError(
          where + ": exactly one of 'expect', 'expect_ambiguous', 'expect_error' is required");
    }
    if (j.contains("expect_ambiguous")) {
      c.kind = LanguageCase::Kind::kAmbiguous;
    } else if (j.contains("expect_error")) {
      c.kind = LanguageCase::Kind::kError;
    } else {
      const nlohmann::json& e = j.at("expect");
      bool ok = e.is_array() && !e.empty();
      for (const nlohmann::json& step : ok ? e : nlohmann::json::array()) {
        ok = ok && step.is_array() && !step.empty();
        std::vector<std::string> pairs;
        for (const nlohmann::json& p : ok ? step : nlohmann::json::array()) {
          ok = ok && p.is_string();
          if (ok) pairs.push_back(p.get<std::string>());
        }
        std::sort(pairs.begin(), pairs.end());
        c.expect.push_back(pairs);
      }
      if (!ok) {
        return absl::InvalidArgumentError(
            where +
            ": /expect: expected a non-empty list of steps, each a non-empty list of "
            "\"object|part|joint|contact|direction\" strings");
      }
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::string CompactPair(const plan::ContactPair& p) {
  std::string joint = p.subject_object ? "@" + *p.subject_object + ":" + p.subject_part
                      : p.joint        ? std::string(core::BodyJointName(*p.joint))
                                       : std::string("none");
  std::string contact = p.IsGetClose() ? "none" : std::string(plan::ContactTypeName(p.type));
  return p.object + "|" + p.part + "|" + joint + "|" + contact + "|" +
         std::string(plan::DirectionName(p.direction));
}

std::vector<std::string> CompactStep(const plan::ContactStep& step) {
  // a carry step is its carry (its hand pairs follow from the object's held points)
  if (step.carry) return {plan::CarrySummary(*step.carry)};
  std::vector<std::string> out;
  for (const plan::ContactPair& p : step.pairs) out.push_back(CompactPair(p));
  std::sort(out.begin(), out.end());
  return out;
}

core::StatusOr<LanguageSummary> RunLanguageCorpus(const std::vector<LanguageCase>& cases,
                                                  const std::string& corpus_dir,
                                                  language::Planner& planner) {
  std::map<std::string, std::unique_ptr<LoadedScene>> scenes;
  LanguageSummary s;
  std::vector<double> latencies;
  for (const LanguageCase& c : cases) {
    auto it = scenes.find(c.scene);
    if (it == scenes.end()) {
      std::string path = c.scene;
      if (path.size() > 5 && path.substr(path.size() - 5) == ".json") {
        path = (std::filesystem::path(corpus_dir) / path).string();
      }
      auto loaded = std::make_unique<LoadedScene>();
      core::StatusOr<world::SceneSpec> spec = world::LoadScene(path);
      if (!spec.ok()) return core::Annotate(spec.status(), "corpus line " + std::to_string(c.line));
      loaded->spec = *spec;
      core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(loaded->spec);
      if (!catalog.ok()) {
        return core::Annotate(catalog.status(), "corpus line " + std::to_string(c.line));
      }
      loaded->catalog = *catalog;
      it = scenes.emplace(c.scene, std::move(loaded)).first;
    }
    language::PlanContext context;
    context.scene = &it->second->catalog;
    for (const world::HumanSpec& h : it->second->spec.humans) {
      context.agents.push_back({h.pos_xy.x(), h.pos_xy.y(), h.yaw_rad, h.posture});
    }
    const auto t0 = std::chrono::steady_clock::now();
    core::StatusOr<language::PlanResult> r = planner.Plan(c.command, context);
    const auto t1 = std::chrono::steady_clock::now();
    LanguageCaseResult res;
    res.c = c;
    res.latency_us = std::chrono::duration<double, std::micro>(t1 - t0).count();
    latencies.push_back(res.latency_us);
    if (r.ok()) {
      std::vector<std::vector<std::string>> got;
      for (const plan::ContactStep& step : r->chain.steps) got.push_back(CompactStep(step));
      for (const auto& step : got) {
        res.got += (res.got.empty() ? "" : " / ");
        for (size_t k = 0; k < step.size(); ++k) res.got += (k ? ", " : "") + step[k];
      }
      res.pass = c.kind == LanguageCase::Kind::kPlan && got == c.expect;
    } else {
      res.got = CodeName(r.status()) + ": " + std::string(r.status().message());
      const std::string msg(r.status().message());
      if (c.kind == LanguageCase::Kind::kAmbiguous) {
        res.pass = absl::IsFailedPrecondition(r.status()) && !msg.empty() && msg.back() == '?';
      } else if (c.kind == LanguageCase::Kind::kError) {
        res.pass = absl::IsInvalidArgument(r.status());
      }
    }
    ++s.cases;
    switch (c.kind) {
      case LanguageCase::Kind::kPlan:
        ++s.plan_cases;
        s.plan_exact += res.pass;
        break;
      case LanguageCase::Kind::kAmbiguous:
        ++s.ambiguous_cases;
        s.ambiguous_refused += res.pass;
        break;
      case LanguageCase::Kind::kError:
        ++s.error_cases;
        s.error_correct += res.pass;
        break;
    }
    s.results.push_back(std::move(res));
  }
  s.median_latency_us = Percentile(latencies, 0.5);
  s.p99_latency_us = Percentile(latencies, 0.99);
  s.max_latency_us = Percentile(latencies, 1.0);
  return s;
}

nlohmann::ordered_json LanguageSummaryJson(const LanguageSummary& s, const std::string& planner,
                                           const std::string& corpus_path) {
  nlohmann::ordered_json j;
  j["suite"] = "language";
  j["planner"] = planner;
  j["corpus"] = corpus_path;
  j["cases"] = s.cases;
  j["plan_cases"] = s.plan_cases;
  j["plan_exact"] = s.plan_exact;
  j["exact_rate"] = s.exact_rate();
  j["ambiguous_cases"] = s.ambiguous_cases;
  j["ambiguous_refused"] = s.ambiguous_refused;
  j["ambiguous_refused_rate"] = s.refused_rate();
  j["error_cases"] = s.error_cases;
  j["error_correct"] = s.error_correct;
  j["error_rate"] = s.error_rate();
  j["median_latency_us"] = s.median_latency_us;
  j["p99_latency_us"] = s.p99_latency_us;
  j["max_latency_us"] = s.max_latency_us;
  nlohmann::ordered_json failed = nlohmann::ordered_json::array();
  for (const LanguageCaseResult& r : s.results) {
    if (r.pass) continue;
    nlohmann::ordered_json f;
    f["line"] = r.c.line;
    f["scene"] = r.c.scene;
    f["command"] = r.c.command;
    f["expected"] = r.c.kind == LanguageCase::Kind::kPlan        ? "plan"
                    : r.c.kind == LanguageCase::Kind::kAmbiguous ? "ambiguous"
                                                                 : "error";
    f["got"] = r.got;
    failed.push_back(f);
  }
  j["failed"] = failed;
  j["git_revision"] = std::string(core::GitRevision());
  return j;
}

}  // namespace simhuman::eval
