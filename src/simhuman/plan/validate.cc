#include "simhuman/plan/validate.h"

#include <optional>
#include <utility>
#include <vector>

namespace simhuman::plan {
namespace {

std::string Quote(std::string_view s) { return "'" + std::string(s) + "'"; }

// the parts of `object` whose name or an alias equals `name` under `key`
template <typename Key>
std::vector<const core::CatalogPart*> MatchParts(const core::CatalogObject& object,
                                                 std::string_view name, Key key) {
  const std::string want = key(name);
  std::vector<const core::CatalogPart*> out;
  for (const core::CatalogPart& part : object.parts) {
    bool hit = key(part.name) == want;
    for (const std::string& alias : part.aliases) hit = hit || key(alias) == want;
    if (hit) out.push_back(&part);
  }
  return out;
}

// exact (case-insensitive, digits kept) first, so a catalog can tell "arm sofa style44" from
// "arm sofa style48" by aliases; then CatalogObject::FindPart's rule (trailing digits ignored).
// More than one part at the deciding stage is ambiguous: never pick one.
std::vector<const core::CatalogPart*> LookupPart(const core::CatalogObject& object,
                                                 std::string_view name) {
  std::vector<const core::CatalogPart*> hits = MatchParts(object, name, [](std::string_view n) {
    return core::NormalizeName(n, core::TrailingDigits::kKeep);
  });
  if (!hits.empty()) return hits;
  return MatchParts(object, name, [](std::string_view n) { return core::NormalizeName(n); });
}

absl::Status Error(const ContactChain& chain, std::string_view pointer,
                   const std::string& message) {
  std::string prefix = chain.source.empty() ? std::string() : chain.source + ": ";
  std::string where = pointer.empty() ? std::string("(root)") : std::string(pointer);
  return absl::InvalidArgumentError(prefix + where + ": " + message);
}

std::string StepPointer(const ContactChain& chain, int s) {
  const ContactStep& step = chain.steps[s];
  if (!step.where.empty()) return step.where;
  return "/steps/" + std::to_string(s);
}

// grounds `name` to one canonical part of `object`; `field` names the pair field in errors
absl::StatusOr<std::string> GroundObjectPart(const ContactChain& chain, int s, int p,
                                             std::string_view field,
                                             const core::CatalogObject& object,
                                             const std::string& name) {
  std::vector<const core::CatalogPart*> parts = LookupPart(object, name);
  if (parts.size() == 1) return parts[0]->name;
  if (parts.size() > 1) {
    std::vector<std::string> names;
    for (const core::CatalogPart* part : parts) names.push_back(part->name);
    return Error(chain, FieldPointer(chain, s, p, field),
                 "ambiguous part " + Quote(name) + " of " + object.id + " (" + object.type +
                     "): it matches " + core::JoinNames(names) + "; name one of them");
  }
  std::vector<std::string> names = object.PartNames();
  return Error(
      chain, FieldPointer(chain, s, p, field),
      "unknown part " + Quote(name) + " of " + object.id + " (" + object.type +
          "); valid parts: " + (names.empty() ? std::string("(none)") : core::JoinNames(names)) +
          " (an object-object pair relates object parts, not body joints)");
}

// an object-object pair: the subject must be a movable object of the scene; both parts must
// be object parts
absl::Status GroundObjectPair(ContactChain& chain, int s, int p, const core::SceneCatalog& scene,
                              const core::CatalogObject& object) {
  ContactPair& pair = chain.steps[s].pairs[p];
  const core::CatalogObject* subject = scene.Find(*pair.subject_object);
  std::vector<std::string> movable;
  for (const core::CatalogObject& o : scene.objects) {
    if (o.movable) movable.push_back(o.id);
  }
  const std::string valid_movable = movable.empty()
                                        ? std::string("the scene has no movable objects")
                                        : "movable objects: " + core::JoinNames(movable);
  if (subject == nullptr) {
    return Error(chain, FieldPointer(chain, s, p, "subject_object"),
                 "unknown object " + Quote(*pair.subject_object) + "; " + valid_movable);
  }
  if (!subject->movable) {
    return Error(chain, FieldPointer(chain, s, p, "subject_object"),
                 subject->id + " (" + subject->type + ") is not movable; " + valid_movable);
  }
  SH_ASSIGN_OR_RETURN(std::string subject_part,
                      GroundObjectPart(chain, s, p, "subject_part", *subject, pair.subject_part));
  SH_ASSIGN_OR_RETURN(std::string part, GroundObjectPart(chain, s, p, "part", object, pair.part));
  pair.subject_part = subject_part;
  pair.part = part;
  return absl::OkStatus();
}

// resolves the pair's body point against its agent's catalog: sets `joint` and the canonical
// `joint_name`
absl::Status GroundJoint(ContactChain& chain, int s, int p, const core::BodyPointCatalog& points) {
  ContactPair& pair = chain.steps[s].pairs[p];
  std::optional<core::BodyJoint> id =
      pair.joint_name.empty() ? pair.joint : points.Find(pair.joint_name);
  if (!id || !points.Contains(*id)) {
    return Error(chain, FieldPointer(chain, s, p, "joint"),
                 "unknown joint " + Quote(pair.JointName()) + " for human " +
                     std::to_string(pair.agent) + "; valid joints: " +
                     core::JoinNames(points.Names()) + " (or 'none' in a get-close pair)");
  }
  pair.joint = id;
  pair.joint_name = points.Name(*id);
  return absl::OkStatus();
}

// of several parts a generic name matched ("arm sofa style44": both arms), the one on the side
// of a sided joint ("left hand" -> "left arm", as UniHSI's Table 8 pairs them); all of them
// when the joint has no side or no part has it
std::vector<const core::CatalogPart*> SameSideParts(
    const std::vector<const core::CatalogPart*>& parts, const std::string& joint_name) {
  for (const char* side : {"left ", "right "}) {
    if (joint_name.rfind(side, 0) != 0) continue;
    std::vector<const core::CatalogPart*> same;
    for (const core::CatalogPart* part : parts) {
      if (part->name.rfind(side, 0) == 0) same.push_back(part);
    }
    if (same.size() == 1) return same;
  }
  return parts;
}

absl::Status GroundPair(ContactChain& chain, int s, int p, const core::SceneCatalog& scene) {
  SH_RETURN_IF_ERROR(CheckPairShape(chain, s, p));
  ContactPair& pair = chain.steps[s].pairs[p];
  if (pair.agent >= scene.num_agents()) {
    return Error(chain, FieldPointer(chain, s, p, "agent"),
                 "agent index " + std::to_string(pair.agent) + " out of range; the scene has " +
                     std::to_string(scene.num_agents()) + " agent(s), valid indices are 0.." +
                     std::to_string(scene.num_agents() - 1));
  }
  const core::CatalogObject* object = scene.Find(pair.object);
  if (object == nullptr) {
    std::vector<std::string> ids = scene.ObjectIds();
    return Error(chain, FieldPointer(chain, s, p, "object"),
                 "unknown object " + Quote(pair.object) +
                     (ids.empty() ? std::string("; the scene has no objects")
                                  : "; valid objects: " + core::JoinNames(ids)));
  }
  pair.part_joint.reset();
  if (pair.IsGetClose()) return absl::OkStatus();
  if (pair.IsObjectPair()) return GroundObjectPair(chain, s, p, scene, *object);
  const core::BodyPointCatalog& points = scene.agents[pair.agent].body_points;
  SH_RETURN_IF_ERROR(GroundJoint(chain, s, p, points));

  std::vector<const core::CatalogPart*> parts = LookupPart(*object, pair.part);
  if (parts.size() > 1) parts = SameSideParts(parts, pair.joint_name);
  if (parts.size() > 1) {
    std::vector<std::string> names;
    for (const core::CatalogPart* part : parts) names.push_back(part->name);
    return Error(chain, FieldPointer(chain, s, p, "part"),
                 "ambiguous part " + Quote(pair.part) + " of " + object->id + " (" + object->type +
                     "): it matches " + core::JoinNames(names) + "; name one of them");
  }
  if (parts.size() == 1) {
    pair.part = parts[0]->name;
    return absl::OkStatus();
  }
  // a body point of the same agent, e.g. "left knee" in "right foot on left knee"
  if (std::optional<core::BodyJoint> joint = points.Find(core::NormalizeName(pair.part))) {
    if (*joint == *pair.joint) {
      return Error(chain, FieldPointer(chain, s, p, "part"),
                   "joint " + Quote(points.Name(*joint)) + " cannot contact itself");
    }
    pair.part_joint = joint;
    pair.part = points.Name(*joint);
    return absl::OkStatus();
  }
  std::vector<std::string> names = object->PartNames();
  return Error(
      chain, FieldPointer(chain, s, p, "part"),
      "unknown part " + Quote(pair.part) + " of " + object->id + " (" + object->type +
          "); valid parts: " + (names.empty() ? std::string("(none)") : core::JoinNames(names)) +
          "; a body joint of the same agent may also be named: " + core::JoinNames(points.Names()));
}

}  // namespace

absl::Status ValidateAndGround(ContactChain& chain, const core::SceneCatalog& scene) {
  if (scene.num_agents() < 1) {
    return Error(
        chain, "",
        "the scene has " + std::to_string(scene.num_agents()) + " agents; at least 1 is needed");
  }
  // ground a copy so that `chain` is untouched on error
  ContactChain grounded = chain;
  if (grounded.steps.empty()) {
    return Error(grounded, grounded.form == ChainForm::kSimhuman ? "/steps" : "",
                 "plan has no steps");
  }
  // carry steps move objects: later steps are grounded against where they were put
  std::optional<core::SceneCatalog> planned;
  for (int s = 0; s < static_cast<int>(grounded.steps.size()); ++s) {
    ContactStep& step = grounded.steps[s];
    if (step.carry) {
      if (!planned) planned = scene;
      SH_RETURN_IF_ERROR(GroundCarryStep(grounded, s, *planned));
      continue;
    }
    if (step.pairs.empty()) {
      std::string where = StepPointer(grounded, s);
      if (grounded.form == ChainForm::kSimhuman) where += "/pairs";
      return Error(grounded, where, "step has no pairs");
    }
    for (int p = 0; p < static_cast<int>(step.pairs.size()); ++p) {
      SH_RETURN_IF_ERROR(GroundPair(grounded, s, p, scene));
    }
  }
  chain = std::move(grounded);
  return absl::OkStatus();
}

absl::StatusOr<ContactChain> ParseAndGround(std::string_view text, std::string_view source,
                                            const core::SceneCatalog& scene) {
  SH_ASSIGN_OR_RETURN(ContactChain chain, ParseContactChain(text, source));
  SH_RETURN_IF_ERROR(ValidateAndGround(chain, scene));
  return chain;
}

absl::StatusOr<ContactChain> LoadAndGroundFile(const std::string& path,
                                               const core::SceneCatalog& scene) {
  SH_ASSIGN_OR_RETURN(ContactChain chain, LoadContactChainFile(path));
  SH_RETURN_IF_ERROR(ValidateAndGround(chain, scene));
  return chain;
}

}  // namespace simhuman::plan
