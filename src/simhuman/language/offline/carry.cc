// Carrying: "carry the box to the bed", "move the armchair next to the sofa", "you two carry the
// long box to the bed", "pick up the box", "put it down here". Planned as carry steps
// (plan/carry.h); the carriers are the first humans of the scene.

#include <cmath>
#include <set>

#include "simhuman/core/json_reader.h"
#include "simhuman/language/offline/objects.h"
#include "simhuman/language/offline/session.h"
#include "simhuman/language/offline_planner.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::language::offline {
namespace {

// destination words with no object type in the catalog
const std::set<std::string> kNoSuchPlace = {"door", "doors", "doorway", "exit", "entrance"};

// the index of the first destination word in t[b, e) ("to", "here" or a relation that does not
// belong to a relative clause of the object's description), or e
size_t DestinationStart(const Tokens& t, size_t b, size_t e) {
  bool relative = false;
  for (size_t i = b; i < e; ++i) {
    if (IsRelativizer(t[i])) {
      relative = true;
      continue;
    }
    if (t[i] == "to" || t[i] == "here") return i;
    std::optional<Rel> r = RelFromWord(t[i]);
    if (r && *r != Rel::kNearest && *r != Rel::kFarthest) {
      if (relative) {
        relative = false;
        continue;
      }
      return i;
    }
  }
  return e;
}

std::string Humans(const std::vector<plan::Carrier>& team) {
  if (team.size() == 1) return "human " + std::to_string(team[0].agent);
  std::string out = "humans ";
  for (size_t k = 0; k < team.size(); ++k) {
    out += (k == 0 ? "" : k + 1 == team.size() ? " and " : ", ") + std::to_string(team[k].agent);
  }
  return out;
}

std::string Carryable(const core::SceneCatalog& scene) {
  std::vector<std::string> out;
  for (const CatalogObject& o : scene.objects) {
    if (o.carry.carryable()) out.push_back(Describe(o));
  }
  return out.empty() ? std::string("none in this scene") : core::JoinNames(out);
}

}  // namespace

bool Session::IsCarryClause(const Tokens& t, size_t b, bool hold_ok, const std::string& c) {
  const size_t e = t.size();
  const size_t dest = DestinationStart(t, b, e);
  if (dest == b) return false;
  core::StatusOr<NounPhrase> np = ParseNounPhrase(t, b, dest, 0, c);
  if (!np.ok()) return false;
  core::StatusOr<const CatalogObject*> o = Resolve(*np, c);
  if (!o.ok() || !np->part.empty()) return false;
  if (*o == held_) return true;
  if (!(*o)->carry.carryable()) return false;
  if (dest == e) return hold_ok;
  if (t[dest] == "here") return true;
  std::optional<Rel> r = RelFromWord(t[dest]);
  return t[dest] == "to" || (r && *r != Rel::kOn);
}

core::StatusOr<std::vector<plan::Carrier>> Session::Team(const CatalogObject& o,
                                                         const std::string& c) {
  const int humans = scene_.num_agents();
  int n = team_ > 0 ? team_ : 0;
  if (n == 0) {
    // as many as the object needs: the smallest team that can lift it (at least two when the
    // command says "together")
    n = o.carry.min_carriers();
    for (const core::CarryLayout& l : o.carry.layouts) {
      if (l.carriers() >= n && o.mass_kg <= core::TeamCapacityKg(l.carriers())) {
        n = l.carriers();
        break;
      }
    }
    if (team_ < 0 && n < 2) n = std::min(2, o.carry.max_carriers());
  }
  if (n > humans) {
    return Invalid("\"" + c + "\": " + Describe(o) + " needs " + std::to_string(n) +
                   " carriers (it weighs " + core::FormatNumber(o.mass_kg) +
                   " kg; one lifts at "
                   "most " +
                   core::FormatNumber(core::TeamCapacityKg(1)) + " kg, a team of " +
                   std::to_string(n) + " " + core::FormatNumber(core::TeamCapacityKg(n)) +
                   " kg) but the scene has " + std::to_string(humans) + " human(s)");
  }
  std::vector<plan::Carrier> team;
  for (int a = 0; a < n; ++a) team.push_back({a, -1});
  return team;
}

absl::Status Session::Carry(const Tokens& t, size_t b, CarryDefault fallback,
                            const std::string& c) {
  const size_t e = t.size();
  const size_t dest = DestinationStart(t, b, e);
  if (dest == b) {
    return Invalid("\"" + c +
                   "\": carry what? name an object; carryable objects: " + Carryable(scene_));
  }
  SH_ASSIGN_OR_RETURN(NounPhrase what, ParseNounPhrase(t, b, dest, 0, c));
  SH_ASSIGN_OR_RETURN(const CatalogObject* o, Resolve(what, c));
  if (!o->carry.carryable()) {
    return Invalid("\"" + c + "\": cannot carry " + Describe(*o) + ": " + o->carry.not_carryable +
                   "; carryable objects: " + Carryable(scene_));
  }
  plan::CarryStep step;
  step.object = o->id;
  std::string where;
  if (dest == e) {
    step.to.kind =
        fallback == CarryDefault::kHold ? plan::CarryTarget::kHold : plan::CarryTarget::kHere;
  } else if (t[dest] == "here") {
    if (dest + 1 < e) {
      return Invalid("did not understand '" + Join(t, dest + 1, e) + "' after 'here' in \"" + c +
                     "\"");
    }
    step.to.kind = plan::CarryTarget::kHere;
  } else {
    const std::optional<Rel> rel = RelFromWord(t[dest]);
    if (rel && *rel == Rel::kOn) {
      return Invalid("\"" + c +
                     "\": a carried object is put down on the floor; say where beside "
                     "something (\"next to the bed\", \"to the left of the sofa\")");
    }
    for (size_t i = dest + 1; i < e; ++i) {
      if (kNoSuchPlace.count(t[i])) {
        return Invalid("\"" + c + "\": this scene has no " + t[i] +
                       " (no object is one); carry it to an object instead. The scene has: " +
                       DescribeSceneObjects(scene_));
      }
    }
    if (dest + 1 >= e) return Invalid("\"" + c + "\": '" + t[dest] + "' needs an object after it");
    SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, dest + 1, e, 0, c));
    SH_ASSIGN_OR_RETURN(const CatalogObject* ref, Resolve(np, c));
    if (ref == o) return Invalid("\"" + c + "\": cannot carry " + Describe(*o) + " to itself");
    step.to.kind = plan::CarryTarget::kBeside;
    step.to.object = ref->id;
    if (rel && *rel != Rel::kNear) step.to.side = ViewerSide(*rel, *ref, viewer_);
    where =
        (rel && *rel != Rel::kNear ? RelText(*rel) : std::string("next to")) + " " + Describe(*ref);
  }
  if (step.to.kind == plan::CarryTarget::kHere && o != held_) {
    return Invalid("\"" + c + "\": " + Describe(*o) + " is not being held; say \"pick up " +
                   "the " + TypeText(o->type) + "\" first, or where to carry it");
  }
  if (o == held_) {
    step.carriers = held_by_;
    if (team_ > 0 && team_ != static_cast<int>(held_by_.size())) {
      return Invalid("\"" + c + "\": " + Describe(*o) + " is held by " + Humans(held_by_) +
                     ", not by " + std::to_string(team_));
    }
  } else {
    SH_ASSIGN_OR_RETURN(step.carriers, Team(*o, c));
  }
  focus_ = o;
  const bool one = step.carriers.size() == 1;
  std::string text = Humans(step.carriers);
  switch (step.to.kind) {
    case plan::CarryTarget::kHold:
      text += (one ? " picks up " : " pick up ") + Describe(*o) +
              (one ? " and holds it" : " and hold it");
      break;
    case plan::CarryTarget::kHere:
      text += (one ? " puts " : " put ") + Describe(*o) + " down where " +
              (one ? "it stands" : "they stand");
      break;
    default:
      text += (one ? " carries " : " carry ") + Describe(*o) + " " + where;
  }
  return AddCarry(*o, std::move(step), text, c);
}

absl::Status Session::AddCarry(const CatalogObject& o, plan::CarryStep step,
                               const std::string& text, const std::string& c) {
  EnsureFree(nullptr);
  if (!planned_) planned_ = scene_;
  // ground it now, against the scene as earlier carry steps leave it, so that a blocked
  // destination or too heavy an object is the command's error
  plan::ContactChain one;
  one.steps.emplace_back();
  one.steps[0].carry = step;
  absl::Status st = plan::GroundCarryStep(one, 0, *planned_);
  if (!st.ok()) {
    std::string msg(st.message());
    const size_t colon = msg.find(": ");  // drop the JSON pointer of the one-step plan
    if (colon != std::string::npos) msg = msg.substr(colon + 2);
    return Invalid("\"" + c + "\": " + msg);
  }
  const plan::CarryStep& grounded = *one.steps[0].carry;
  std::string said = text;
  if (grounded.goal) {
    said += std::string(grounded.carriers.size() == 1 ? " and puts" : " and put") +
            " it down at (" + core::FormatNumber(std::round(grounded.goal->pos.x() * 100) / 100) +
            ", " + core::FormatNumber(std::round(grounded.goal->pos.y() * 100) / 100) + ")";
  }
  held_ = grounded.to.kind == plan::CarryTarget::kHold ? &o : nullptr;
  held_by_ = grounded.carriers;
  // the first carrier ends at its stand point by the object
  const core::CatalogObject& moved = *planned_->Find(o.id);
  const core::CarryLayout& layout = *moved.carry.ForTeam(static_cast<int>(held_by_.size()));
  const Eigen::Vector3d stand =
      moved.pose.Apply(layout.holds[static_cast<size_t>(held_by_[0].hold)].stand_local);
  pos_ = {stand.x(), stand.y()};
  posture_ = Posture::kStand;
  on_ = nullptr;
  StepDraft d;
  d.step.carry = std::move(step);
  d.object = &o;
  d.text = said;
  Push(std::move(d));
  return absl::OkStatus();
}

}  // namespace simhuman::language::offline
