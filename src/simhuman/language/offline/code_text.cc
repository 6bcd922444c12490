// Commands written as code (issue 20, set E): calls ("sit(chair000); lean('forward')"), method
// calls on an object ("armchair004.sit()"), keyword arguments ("stack(box001, on=box004)",
// "touch(box004.top, hand='left')"), JSON key/value objects ({"action": "sit", "target":
// "chair"}) and a loop over a list of step strings. A small pre-pass turns them into the words
// they stand for before tokenizing; plain English passes through unchanged.

#include <regex>
#include <set>
#include <string>
#include <string_view>

#include "simhuman/language/offline/clauses.h"

namespace simhuman::language::offline {
namespace {

std::string Trim(std::string s) {
  const char* kSpace = " \t\r\n'\"";
  const size_t b = s.find_first_not_of(kSpace);
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(kSpace);
  return s.substr(b, e + 1 - b);
}

std::string Spaced(std::string s) {
  for (char& c : s) {
    if (c == '_') c = ' ';
  }
  return s;
}

bool IsHandKey(const std::string& k) { return k == "hand" || k == "hands" || k == "side"; }

// one argument of a call: "box004.top" is "the top of box004", "hand='left'" "with left hand",
// "on=box004" "on box004"
std::string Argument(const std::string& raw) {
  const std::string a = Trim(raw);
  const size_t eq = a.find('=');
  if (eq != std::string::npos) {
    const std::string k = Trim(a.substr(0, eq));
    const std::string v = Trim(a.substr(eq + 1));
    if (IsHandKey(k)) return "with " + v + " hand";
    return Spaced(k) + " " + Argument(v);
  }
  const size_t dot = a.find('.');
  if (dot != std::string::npos && dot > 0 && dot + 1 < a.size()) {
    return "the " + Spaced(a.substr(dot + 1)) + " of " + a.substr(0, dot);
  }
  return Spaced(a);
}

std::string Arguments(const std::string& args) {
  std::string out;
  size_t b = 0;
  while (b <= args.size()) {
    size_t e = args.find(',', b);
    if (e == std::string::npos) e = args.size();
    const std::string a = Argument(args.substr(b, e - b));
    if (!a.empty()) out += " " + a;
    b = e + 1;
  }
  return out;
}

// {"key": "value", ...}: the action key's value is the verb, the target's its object, a body
// part's the place it rests ("hands": "stomach"), any other key a verb of its own ("pick",
// "place_on")
std::string Json(const std::string& text) {
  static const std::regex kPair(R"(["']([A-Za-z_ ]+)["']\s*:\s*["']([^"']*)["'])");
  static const std::set<std::string> kAction = {"action", "verb", "do", "cmd", "command", "task"};
  static const std::set<std::string> kTarget = {"target", "object", "obj", "on", "at", "to"};
  static const std::set<std::string> kBody = {"hands",  "hand",  "feet", "foot",
                                              "elbows", "elbow", "head", "knees"};
  std::string out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kPair);
       it != std::sregex_iterator(); ++it) {
    const std::string k = (*it)[1];
    const std::string v = (*it)[2];
    if (kAction.count(k) || kTarget.count(k)) {
      out += " " + Spaced(v);
    } else if (kBody.count(k)) {
      out += ", " + k + " on " + Spaced(v);
    } else {
      out += std::string(out.empty() ? "" : ",") + " " + Spaced(k) + " " + Spaced(v);
    }
  }
  return out;
}

}  // namespace

std::string CodeToWords(std::string_view command) {
  std::string s(command);
  if (s.size() > 1024 || s.find_first_of("({[") == std::string::npos) return s;
  // a loop over step strings: the steps in order
  static const std::regex kList(R"(\[\s*((['"][^'"]*['"]\s*,?\s*)+)\])");
  static const std::regex kQuoted(R"(['"]([^'"]*)['"])");
  std::smatch m;
  if (std::regex_search(s, m, kList)) {
    const std::string items = m[1];
    std::string out;
    for (auto it = std::sregex_iterator(items.begin(), items.end(), kQuoted);
         it != std::sregex_iterator(); ++it) {
      out += std::string(out.empty() ? "" : ", then ") + (*it)[1].str();
    }
    return out;
  }
  if (s.find('{') != std::string::npos && s.find(':') != std::string::npos) {
    const std::string j = Json(s);
    if (!j.empty()) return j;
  }
  // obj.method(args) and name(args): the call's words, the object last
  static const std::regex kMethod(R"(\b([A-Za-z]+[0-9]+)\.([A-Za-z_]+)\(([^()]*)\))");
  static const std::regex kCall(R"(\b([A-Za-z][A-Za-z_]*)\(([^()]*)\))");
  s = std::regex_replace(s, kMethod, "$2($3) $1");
  std::string out;
  auto begin = s.cbegin();
  for (auto it = std::sregex_iterator(s.begin(), s.end(), kCall); it != std::sregex_iterator();
       ++it) {
    out.append((*it).prefix().str());
    out += Spaced((*it)[1].str()) + Arguments((*it)[2].str());
    begin = (*it)[0].second;
  }
  out.append(begin, s.cend());
  return out;
}

}  // namespace simhuman::language::offline
