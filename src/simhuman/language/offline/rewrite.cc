#include "simhuman/language/offline/rewrite.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <utility>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/spatial.h"

namespace simhuman::language::offline {
namespace {

// every word the lexicon reads (not corrected)
const std::set<std::string>& Vocabulary() {
  static const auto* words = [] {
    auto* w = new std::set<std::string>();
    for (const auto& [from, to] : Phrases()) w->insert(from.begin(), from.end());
    for (const auto& [from, to] : Synonyms()) w->insert(from);
    w->insert(Fillers().begin(), Fillers().end());
    return w;
  }();
  return *words;
}

// the words a slip is corrected to: objects, parts, colours, body words, function words
const std::set<std::string>& Targets() {
  static const auto* words = [] {
    auto* w = new std::set<std::string>{"the",   "your",  "with",  "then",   "and",
                                        "hand",  "hands", "elbow", "elbows", "knee",
                                        "knees", "foot",  "feet",  "legs",   "stomach"};
    for (const auto& [from, to] : TypeWords()) {
      if (!to.empty()) w->insert(from);
    }
    for (const auto& [from, to] : PartWords()) w->insert(from);
    for (const auto& [from, to] : Synonyms()) {
      if (TypeWords().count(to) && !TypeWords().at(to).empty()) w->insert(from);
    }
    w->insert(Colors().begin(), Colors().end());
    return w;
  }();
  return *words;
}

bool IsTransposition(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  size_t i = 0;
  while (i < a.size() && a[i] == b[i]) ++i;
  return i + 1 < a.size() && a[i] == b[i + 1] && a[i + 1] == b[i] &&
         a.compare(i + 2, std::string::npos, b, i + 2, std::string::npos) == 0;
}

}  // namespace

int EditDistance(const std::string& a, const std::string& b) {
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

Tokens CorrectTypos(const Tokens& raw) {
  Tokens out = raw;
  for (std::string& w : out) {
    if (w.size() < 3 || Known(w) || Vocabulary().count(w)) continue;
    if (std::any_of(w.begin(), w.end(), [](char c) { return std::isdigit(c) != 0; })) continue;
    const int allowed = w.size() >= 8 ? 2 : w.size() >= 5 ? 1 : 0;
    std::string best;
    int best_d = 3, count = 0;
    for (const std::string& t : Targets()) {
      const int d = IsTransposition(w, t) ? 1 : EditDistance(w, t);
      if (d > allowed && !(d == 1 && IsTransposition(w, t))) continue;
      if (d < best_d) {
        best = t;
        best_d = d;
        count = 1;
      } else if (d == best_d) {
        ++count;
      }
    }
    if (count == 1) w = best;
  }
  return out;
}

void JoinClauses(std::vector<ClauseWords>& clauses) {
  for (size_t k = 0; k + 1 < clauses.size(); ++k) {
    Tokens& a = clauses[k].words;
    Tokens& b = clauses[k + 1].words;
    if (a.size() == 1 && a[0] == "sit" && !b.empty() && b[0] == "type") {
      a = {"sit", "at", "keyboard"};
      continue;
    }
    // "grab A [with your H hand]" + "put it REL B" -> "put A REL B [with your H hand]"
    const bool put = b.size() >= 3 && (b[0] == "put" || b[0] == "move" || b[0] == "stack") &&
                     b[1] == "it" && RelFromWord(b[2]).has_value();
    if (a.size() < 2 || a[0] != "grab" || !put) continue;
    const size_t with =
        static_cast<size_t>(std::find(a.begin(), a.end(), std::string("with")) - a.begin());
    Tokens joined = {"put"};
    joined.insert(joined.end(), a.begin() + 1, a.begin() + static_cast<long>(with));
    joined.insert(joined.end(), b.begin() + 2, b.end());
    joined.insert(joined.end(), a.begin() + static_cast<long>(with), a.end());
    clauses[k].words = std::move(joined);
    clauses.erase(clauses.begin() + static_cast<long>(k) + 1);
  }
}

}  // namespace simhuman::language::offline
