// Object references: resolving a parsed noun phrase to one scene object (by id, type, colour,
// part, spatial relation, selection or pronoun), and the clarifying question when several
// objects fit.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "simhuman/language/offline/objects.h"
#include "simhuman/language/offline/session.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::language::offline {

core::StatusOr<std::vector<const CatalogObject*>> Session::Candidates(const NounPhrase& np,
                                                                      const std::string& clause) {
  std::vector<const CatalogObject*> c;
  if (np.pronoun) {
    if (focus_ == nullptr) {
      return Invalid("'" + np.text + "' in \"" + clause +
                     "\" refers to nothing mentioned before; name the object. The scene has: " +
                     DescribeSceneObjects(scene_));
    }
    c.push_back(focus_);
  } else if (!np.id.empty()) {
    const CatalogObject* o = scene_.Find(np.id);
    if (o == nullptr) {
      return Invalid("there is no object '" + np.id + "' in this scene (\"" + clause +
                     "\"); the scene has: " + DescribeSceneObjects(scene_));
    }
    c.push_back(o);
  } else {
    // a high stool is a stool too; an armchair is a chair when no plain chair fits ("the red
    // chair" for the only red seat, an armchair)
    for (bool wide : {false, true}) {
      for (const CatalogObject& o : scene_.objects) {
        if (!np.type.empty() && o.type != np.type &&
            !(np.type == "stool" && o.type == "high_stool") &&
            !(wide && np.type == "chair" && o.type == "armchair")) {
          continue;
        }
        if (!np.color.empty() && o.color != np.color) continue;
        if (np.type.empty() && !np.part.empty() && PartsNamed(o, np.part).empty()) continue;
        c.push_back(&o);
      }
      if (!c.empty() || np.type != "chair") break;
    }
    if (c.empty()) {
      return Invalid("there is no " + NounOf(np) + " in this scene (\"" + clause +
                     "\"); the scene has: " + DescribeSceneObjects(scene_));
    }
  }
  for (const NounPhrase::Relation& r : np.relations) {
    SH_ASSIGN_OR_RETURN(const CatalogObject* ref, Resolve(*r.ref, clause));
    std::vector<const CatalogObject*> kept;
    for (const CatalogObject* o : c) {
      if (o == ref) continue;
      bool ok = true;
      if (r.rel == Rel::kOn) ok = RestsOn(*o, *ref);
      if (r.rel == Rel::kLeftOf || r.rel == Rel::kRightOf || r.rel == Rel::kFrontOf ||
          r.rel == Rel::kBehind) {
        ok = HoldsSide(r.rel, *o, *ref, viewer_);
      }
      if (ok) kept.push_back(o);
    }
    if ((r.rel == Rel::kNear || r.rel == Rel::kNearest || r.rel == Rel::kFarthest) &&
        !kept.empty()) {
      // the nearest (farthest) ones; ties stay ambiguous
      const double sign = r.rel == Rel::kFarthest ? -1.0 : 1.0;
      double best = 1e300;
      for (const CatalogObject* o : kept) best = std::min(best, sign * CentreDistance(*o, *ref));
      std::vector<const CatalogObject*> top;
      for (const CatalogObject* o : kept) {
        if (sign * CentreDistance(*o, *ref) <= best + kTieM) top.push_back(o);
      }
      kept = top;
    }
    if (kept.empty()) {
      std::vector<std::string> ids;
      for (const CatalogObject* o : c) ids.push_back(Describe(*o));
      return Invalid("no " + NounOf(np) + " is " + RelText(r.rel) + " " + Describe(*ref) + " (\"" +
                     clause + "\"); candidates: " + core::JoinNames(ids));
    }
    c = kept;
  }
  if (np.select != Select::kNone && c.size() > 1) {
    auto key = [&](const CatalogObject* o) {
      switch (np.select) {
        case Select::kLeft:
          return -viewer_.Local(o->pose.pos.x() - viewer_.x, o->pose.pos.y() - viewer_.y).second;
        case Select::kRight:
          return viewer_.Local(o->pose.pos.x() - viewer_.x, o->pose.pos.y() - viewer_.y).second;
        case Select::kBig:
          return -Volume(*o);
        case Select::kSmall:
          return Volume(*o);
        case Select::kFlat:
          return Height(*o);
        case Select::kNear:
          return FootprintDistance(*o, pos_);
        case Select::kFar:
          return -FootprintDistance(*o, pos_);
        case Select::kNone:
          break;
      }
      return 0.0;
    };
    const bool volume =
        np.select == Select::kBig || np.select == Select::kSmall || np.select == Select::kFlat;
    double best = 1e300;
    for (const CatalogObject* o : c) best = std::min(best, key(o));
    std::vector<const CatalogObject*> top;
    for (const CatalogObject* o : c) {
      const double tie = volume ? 0.05 * std::abs(best) + 1e-9 : kTieM;
      if (key(o) <= best + tie) top.push_back(o);
    }
    c = top;
  }
  // "go to the box, touch the top": a part named alone is the part of the object in focus (the
  // one sat or lain on first) when that object has it
  if (c.size() > 1 && !np.has_type && np.color.empty() && np.id.empty() && !np.part.empty() &&
      np.relations.empty() && np.select == Select::kNone) {
    for (const CatalogObject* f : {on_, focus_}) {
      if (f != nullptr && std::find(c.begin(), c.end(), f) != c.end()) return std::vector{f};
    }
  }
  return c;
}

// "left of the green sphere": a relation to the nearest object that colour and type name
// uniquely and that is not one of the candidates
std::string Session::Landmark(const CatalogObject& c,
                              const std::vector<const CatalogObject*>& exclude) const {
  const CatalogObject* best = nullptr;
  double best_d = 1e300;
  for (const CatalogObject& o : scene_.objects) {
    if (std::find(exclude.begin(), exclude.end(), &o) != exclude.end()) continue;
    int same = 0;
    for (const CatalogObject& p : scene_.objects) same += p.type == o.type && p.color == o.color;
    if (same != 1) continue;
    double d = CentreDistance(c, o);
    if (d < best_d) {
      best_d = d;
      best = &o;
    }
  }
  if (best == nullptr) return "";
  Rel rel = RestsOn(c, *best) ? Rel::kOn : SideRelation(c, *best, viewer_);
  return RelText(rel) + " the " + best->color + " " + TypeText(best->type);
}

std::string Session::Ambiguity(const NounPhrase& np,
                               const std::vector<const CatalogObject*>& c) const {
  std::vector<std::string> options;
  std::set<std::string> seen;
  for (const CatalogObject* o : c) {
    std::string where = Landmark(*o, c);
    if (where.empty() || seen.count(where)) {
      char buf[64];
      std::snprintf(buf, sizeof(buf), "at (%.2f, %.2f)", o->pose.pos.x(), o->pose.pos.y());
      where = buf;
    }
    seen.insert(where);
    options.push_back("the one " + where + " (" + o->id + ")");
  }
  std::string list;
  for (size_t i = 0; i < options.size(); ++i) {
    if (i > 0) list += i + 1 == options.size() ? " or " : ", ";
    list += options[i];
  }
  return "Which " + NounOf(np) + ": " + list + "?";
}

core::StatusOr<const CatalogObject*> Session::Resolve(const NounPhrase& np,
                                                      const std::string& clause,
                                                      const std::string& need_part) {
  SH_ASSIGN_OR_RETURN(std::vector<const CatalogObject*> c, Candidates(np, clause));
  if (c.size() > 1 && !need_part.empty()) {
    // a type-less description ("sit on the red one") keeps the objects that fit the request
    std::vector<const CatalogObject*> fit;
    for (const CatalogObject* o : c) {
      if (HasPart(*o, need_part)) fit.push_back(o);
    }
    if (!fit.empty() && np.type.empty()) c = fit;
  }
  if (c.size() > 1) return Question(Ambiguity(np, c));
  return c[0];
}

// the single part of `o` that `np` names; `side` picks an arm when the words do not
core::StatusOr<std::string> ResolvePart(const CatalogObject& o, const NounPhrase& np,
                                        const std::string& side, const std::string& clause) {
  std::string word = np.part;
  if (word == "arm" && !np.part_side.empty()) word = np.part_side + " arm";
  if (word == "seat") word = "seat surface";
  std::vector<const core::CatalogPart*> parts = PartsNamed(o, word);
  // "the top of the stool": what faces up on an object without a top
  for (const char* up : {"seat surface", "board", "mattress"}) {
    if (parts.empty() && (word == "top" || word == "surface")) parts = PartsNamed(o, up);
  }
  if (parts.size() > 1 && (side == "left" || side == "right")) {
    std::vector<const core::CatalogPart*> sided;
    for (const core::CatalogPart* p : parts) {
      if (p->name.rfind(side, 0) == 0) sided.push_back(p);
    }
    if (!sided.empty()) parts = sided;
  }
  if (parts.empty()) {
    return Invalid(Describe(o) + " has no part '" + np.part + "' (\"" + clause +
                   "\"); its parts: " + PartsText(o));
  }
  if (parts.size() > 1) {
    std::vector<std::string> names;
    for (const core::CatalogPart* p : parts) names.push_back("the " + p->name);
    return Question("Which " + np.part + " of " + Describe(o) + ": " +
                    (names.size() == 2 ? names[0] + " or " + names[1] : core::JoinNames(names)) +
                    "?");
  }
  return parts[0]->name;
}

}  // namespace simhuman::language::offline
