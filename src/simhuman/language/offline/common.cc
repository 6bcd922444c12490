#include "simhuman/language/offline/common.h"

#include <algorithm>

namespace simhuman::language::offline {

std::string Join(const Tokens& tokens, size_t b, size_t e) {
  std::string out;
  for (size_t i = b; i < e && i < tokens.size(); ++i) {
    if (!out.empty()) out += ' ';
    out += tokens[i];
  }
  return out;
}
std::string Join(const Tokens& tokens) { return Join(tokens, 0, tokens.size()); }

bool Has(const Tokens& t, size_t b, size_t e, const std::string& w) {
  return std::find(t.begin() + static_cast<long>(std::min(b, t.size())),
                   t.begin() + static_cast<long>(std::min(e, t.size())),
                   w) != t.begin() + static_cast<long>(std::min(e, t.size()));
}

size_t Find(const Tokens& t, size_t b, size_t e, const std::set<std::string>& words) {
  for (size_t i = b; i < e; ++i) {
    if (words.count(t[i])) return i;
  }
  return e;
}

std::string SideBefore(const Tokens& t, size_t b, size_t i) {
  while (i > b) {
    --i;
    if (t[i] == "your") continue;
    if (t[i] == "left" || t[i] == "right" || t[i] == "both") return t[i];
    return "";
  }
  return "";
}

}  // namespace simhuman::language::offline
