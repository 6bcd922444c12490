// What a plan leaves out of what its command names: the rules may read a clause wrongly without
// refusing it (a verbless pose skipped, a second task dropped), and then the fallback, which only
// reads what the rules refuse, never runs. Uncovered() counts the objects and limbs a command
// names that its plan does not use, so that OfflinePlanner can ask the fallback for a plan that
// uses more of them.

#include <set>
#include <string>

#include "simhuman/core/body_joint.h"
#include "simhuman/language/offline/fallback.h"
#include "simhuman/language/offline/lexicon.h"

namespace simhuman::language::offline {
namespace {

bool TypeFits(const std::string& named, const std::string& type) {
  return named == type || (named == "chair" && type == "armchair") ||
         (named == "stool" && type == "high_stool");
}

// the limb a word names, as it appears in a joint's name ("hand", "elbow", "foot", "knee")
std::string Limb(const std::string& w) {
  if (w == "hand" || w == "hands") return "hand";
  if (w == "elbow" || w == "elbows") return "elbow";
  if (w == "foot" || w == "feet") return "foot";
  if (w == "knee" || w == "knees" || w == "other_knee") return "knee";
  return "";
}

}  // namespace

int Uncovered(const Tokens& words, const PlanResult& plan, const core::SceneCatalog& scene) {
  std::set<std::string> types, ids, limbs;  // what the plan uses
  for (const ContactStep& s : plan.chain.steps) {
    if (s.carry) return 0;  // a carry's pairs follow from the held object: not compared
    for (const ContactPair& p : s.pairs) {
      for (const std::string* id : {&p.object, p.subject_object ? &*p.subject_object : nullptr}) {
        if (id == nullptr) continue;
        ids.insert(*id);
        if (const CatalogObject* o = scene.Find(*id)) types.insert(o->type);
      }
      if (p.joint) limbs.insert(std::string(core::BodyJointName(*p.joint)));
      limbs.insert(p.part);  // "left knee" when a foot rests on it
    }
  }
  std::set<std::string> missing;
  for (const std::string& w : words) {
    auto t = TypeWords().find(w);
    if (t != TypeWords().end() && !t->second.empty()) {
      bool in_scene = false, used = false;
      for (const CatalogObject& o : scene.objects)
        in_scene = in_scene || TypeFits(t->second, o.type);
      for (const std::string& u : types) used = used || TypeFits(t->second, u);
      if (in_scene && !used) missing.insert(t->second);
    } else if (scene.Find(w) != nullptr && !ids.count(w)) {
      missing.insert(w);
    } else if (const std::string limb = Limb(w); !limb.empty()) {
      bool used = false;
      for (const std::string& u : limbs) used = used || u.find(limb) != std::string::npos;
      if (!used) missing.insert(limb);
    }
  }
  return static_cast<int>(missing.size());
}

}  // namespace simhuman::language::offline
