#include "simhuman/web/clarify.h"

#include <algorithm>
#include <cctype>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_replace.h"
#include "absl/strings/strip.h"

namespace simhuman::web {
namespace {

struct Candidate {
  std::string id;
  std::string description;  // lower case, e.g. "the one on the brown table"
};

const core::CatalogObject* Find(const core::SceneCatalog& catalog, const std::string& id) {
  for (const core::CatalogObject& o : catalog.objects) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

// the "(id)" groups of the question, each with the text before it back to a ',' ':' or " or "
std::vector<Candidate> Candidates(const std::string& question, const core::SceneCatalog& catalog) {
  std::vector<Candidate> out;
  size_t start = question.find(':');
  start = start == std::string::npos ? 0 : start + 1;
  for (size_t open = question.find('('); open != std::string::npos;
       open = question.find('(', open + 1)) {
    const size_t close = question.find(')', open);
    if (close == std::string::npos) break;
    const std::string id = question.substr(open + 1, close - open - 1);
    if (!Find(catalog, id)) continue;  // "(0.85, 0.00)" is a position, not an id
    absl::string_view text = question;
    text = absl::StripAsciiWhitespace(text.substr(start, open - start));
    absl::ConsumePrefix(&text, ",");
    text = absl::StripLeadingAsciiWhitespace(text);
    absl::ConsumePrefix(&text, "or ");
    const std::string description = absl::AsciiStrToLower(absl::StripAsciiWhitespace(text));
    out.push_back({id, description});
    start = close + 1;
  }
  return out;
}

std::string Listing(const std::vector<Candidate>& cands) {
  std::string s;
  for (size_t i = 0; i < cands.size(); ++i) {
    s += (i ? ", " : "") + std::to_string(i + 1) + " = " + cands[i].id + " (" +
         cands[i].description + ")";
  }
  return s;
}

}  // namespace

core::StatusOr<std::string> AnswerQuestion(const std::string& command, const std::string& question,
                                           const std::string& answer,
                                           const core::SceneCatalog& catalog) {
  const std::vector<Candidate> cands = Candidates(question, catalog);
  if (cands.empty()) {
    return absl::InvalidArgumentError(
        "the question lists no objects to choose from; type the "
        "command again naming one object");
  }
  const std::string a = absl::AsciiStrToLower(absl::StripAsciiWhitespace(answer));
  std::vector<const Candidate*> hits;
  int number = 0;
  if (absl::SimpleAtoi(a, &number) && number >= 1 && number <= static_cast<int>(cands.size())) {
    hits.push_back(&cands[number - 1]);
  }
  for (const Candidate& c : cands) {
    if (hits.empty() && a.find(absl::AsciiStrToLower(c.id)) != std::string::npos)
      hits.push_back(&c);
  }
  if (hits.empty() && !a.empty()) {
    absl::string_view bare = a;
    for (const char* lead : {"the one ", "one "}) absl::ConsumePrefix(&bare, lead);
    for (const Candidate& c : cands) {
      if (c.description.find(std::string(bare)) != std::string::npos) hits.push_back(&c);
    }
  }
  if (hits.size() != 1) {
    return absl::InvalidArgumentError("the answer '" + answer + "' " +
                                      (hits.empty() ? "matches none" : "matches several") +
                                      " of the choices; answer with a number, an id or a "
                                      "description: " +
                                      Listing(cands));
  }
  // name the chosen object in the command: "the <type>" or "<type>" becomes its id
  const core::CatalogObject* obj = Find(catalog, hits[0]->id);
  std::string type = absl::StrReplaceAll(obj->type, {{"_", " "}});
  std::string lower = absl::AsciiStrToLower(command);
  for (const std::string& phrase : {"the " + type, type}) {
    const size_t at = lower.find(phrase);
    if (at != std::string::npos) {
      return command.substr(0, at) + obj->id + command.substr(at + phrase.size());
    }
  }
  return command + " (" + obj->id + ")";
}

}  // namespace simhuman::web
