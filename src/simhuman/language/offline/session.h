#pragma once
/// The offline planner's state while it reads one command (internal to language/): where the
/// human is, its posture, what it sits or lies on, the object last referred to ("it"), and the
/// steps planned so far. One Session per OfflinePlanner::Plan() call; not shared.
///
/// Its member functions live with their concept:
/// - references.cc: resolving noun phrases to scene objects (and clarifying questions);
/// - steps.cc: step builders (get close, implied stand-up and get-close steps, sit, lie) and
///   chain assembly (Finish);
/// - poses.cc: sitting and lying poses ("hands on the knees", "lean back", "knees up", ...);
/// - body_verbs.cc: sit, lie, rest, go, stand up, touch/reach;
/// - tabletop.cc: put/place/stack an object on or next to another;
/// - carry.cc: carry, bring, lift, pick up and put down objects, alone or as a team;
/// - clauses.cc: the clause dispatcher (which verb handler reads a clause).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/language/offline/common.h"
#include "simhuman/language/offline/noun_phrase.h"
#include "simhuman/language/offline/spatial.h"
#include "simhuman/language/planner.h"

namespace simhuman::language::offline {

/// The human's posture as planned so far.
enum class Posture { kStand, kSit, kLie };

/// A sitting or lying pose added to the current sit or lie step (UniHSI's interaction
/// variants).
enum class VariantKind {
  kHandsOnArms,
  kHandsOffArms,
  kElbowsOnArms,
  kHandsOnKnees,
  kHandsOnStomach,
  kFootOnKnee,
  kLeanForward,
  kLeanBack,
  kKneesUp,
  kHandsOnPillow,
  kOnSide,
  kHeadUp,
  kHeadOnPillow,  // the default lying pose said out loud ("with your head on the pillow")
};

/// How a sit-like verb treats its object: sit, lie, rest (sit on a seat, lie on a bed) or
/// recline (sit and lean back on a seat, lie on a bed).
enum class SitMode { kSit, kLie, kRest, kRecline };

/// One pose and the limbs it uses.
struct Variant {
  VariantKind kind;
  std::string side;       // "left", "right" or "both" (the limb; for kOnSide the side lain on)
  std::string knee_side;  // kFootOnKnee: the knee's side
};

/// A step being planned: its pairs, its text, and what kind of step it is (poses merge into
/// the sit or lie step they follow).
struct StepDraft {
  ContactStep step;
  std::string text;
  enum Kind { kMove, kSit, kLie, kOther } kind = kOther;
  const CatalogObject* object = nullptr;
  size_t base_pairs = 0;                   // pairs of the sit/lie itself; poses come after
  int clause = -1;                         // the clause that made the step
  std::vector<std::string> variant_texts;  // the poses in words, appended to the text
};

/// A contact pair between body joint `joint` and `part` of `o`.
ContactPair Pair(const CatalogObject& o, const std::string& part, BodyJoint joint, ContactType type,
                 Direction dir);
/// `left` for side "left", else `right`.
BodyJoint SideJoint(const std::string& side, BodyJoint left, BodyJoint right);
/// {"left", "right"} for "both", else {side}.
std::vector<std::string> Sides(const std::string& side);

/// The single part of `o` that `np` names (canonical name); `side` ("left"/"right") picks an
/// arm when the words do not. kInvalidArgument when `o` has no such part, kFailedPrecondition
/// (a question) when several parts match.
core::StatusOr<std::string> ResolvePart(const CatalogObject& o, const NounPhrase& np,
                                        const std::string& side, const std::string& clause);

/// See the file comment.
class Session {
 public:
  /// Starts from PlanContext::agents[0] (a standing human at the origin facing +x when there is
  /// none); a sitting or lying start sits or lies on the nearest object that allows it.
  /// `scene` must outlive the session.
  Session(const core::SceneCatalog& scene, const PlanContext& context);

  /// Plans one clause (normalised tokens without "then"/"and" separators) and appends its
  /// steps. Errors follow Planner's status codes and quote the clause.
  absl::Status Clause(const Tokens& t);
  /// The unknown-word policy (clauses.cc): drops unknown words inside a clause; an error for an
  /// unknown action (verb position), object (after a relation, colour or size, or last) or id.
  absl::Status SkipUnknownWords(Tokens& t, const std::string& c) const;

  /// Says how the next clause was joined to the one before: `sequenced` after "then", a comma
  /// or a full stop (a pose said there starts a new step), false after a bare "and".
  void NextClause(bool sequenced) {
    sequenced_ = sequenced;
    ++clause_;
  }

  /// The grounded plan of all clauses so far. kInvalidArgument when no clause asked for
  /// anything; kInternal when the plan fails plan::ValidateAndGround() (a bug).
  core::StatusOr<PlanResult> Finish();

 private:
  // ---- references (references.cc)
  core::StatusOr<const CatalogObject*> Resolve(const NounPhrase& np, const std::string& clause,
                                               const std::string& need_part = "");
  core::StatusOr<std::vector<const CatalogObject*>> Candidates(const NounPhrase& np,
                                                               const std::string& clause);
  std::string Ambiguity(const NounPhrase& np, const std::vector<const CatalogObject*>& c) const;
  std::string Landmark(const CatalogObject& c,
                       const std::vector<const CatalogObject*>& exclude) const;

  // ---- steps (steps.cc)
  void EnsureFree(const CatalogObject* target);
  void EnsureNear(const CatalogObject& target);
  void AddGetClose(const CatalogObject& o, Direction side, const std::string& text);
  absl::Status AddSit(const CatalogObject& o);
  absl::Status AddLie(const CatalogObject& o);
  void Push(StepDraft d) {
    d.clause = clause_;
    left_seat_ = false;
    steps_.push_back(std::move(d));
  }

  // ---- poses (poses.cc)
  absl::Status AddVariant(const Variant& v, const std::string& clause);
  core::StatusOr<std::vector<ContactPair>> VariantPairs(const Variant& v,
                                                        const std::string& clause) const;
  void MergeIntoPoseStep(const std::vector<ContactPair>& pairs, const std::string& what);
  /// A draft holding only the pairs of the current sit or lie (the seat pair repeated).
  StepDraft PostureDraft() const;
  /// Sits or lies first when a pose is asked while standing ("lean back in the armchair",
  /// "cross your legs" with one seat in the scene); t[b, e) is the pose clause.
  absl::Status ImpliedBase(const Variant& v, const Tokens& t, size_t b, size_t e,
                           const std::string& c);
  /// The one object of the scene with all of `parts` (the one sat/lain on or last referred to
  /// first); a question listing them when several fit.
  core::StatusOr<const CatalogObject*> OnlyObjectWith(const std::vector<std::string>& parts,
                                                      const std::string& verb,
                                                      const std::string& c) const;
  core::StatusOr<std::optional<Variant>> ParseVariant(const Tokens& t, size_t b, size_t e,
                                                      const std::string& c) const;

  // ---- clause kinds (body_verbs.cc, tabletop.cc)
  absl::Status SitOrLie(const Tokens& t, size_t b, SitMode mode, const std::string& c);
  core::StatusOr<const CatalogObject*> SeatAt(const CatalogObject& o, const std::string& c) const;
  /// The one seat within kSeatByM of `o` when `o` (the object last referred to) is no seat
  /// itself; nullptr otherwise ("walk to the desk and sit down").
  const CatalogObject* SeatBy(const CatalogObject* o) const;
  absl::Status SitPose(const Tokens& t, size_t j, const std::string& c);
  absl::Status Type(const Tokens& t, size_t b, const std::string& c);
  /// "see the armchair? sit in it": the object becomes "it"; "use the chair / the laptop": rest
  /// on it or type on it. t[i] is the verb.
  absl::Status NoticeOrUse(const Tokens& t, size_t i, const std::string& c);
  /// A sentence that is only a noun phrase ("The chair. Sit on it.", "Red box, pick up.", "the
  /// BOX." after a touch): the object becomes "it", no step. nullopt when t[i, ...) is no such
  /// phrase (or the clause followed a bare "and": "sit on the chair and the sofa").
  std::optional<absl::Status> Mention(const Tokens& t, size_t i, const std::string& c);
  absl::Status Go(const Tokens& t, size_t b, const std::string& c);
  absl::Status StandUp(const std::string& c);
  /// `in_pose`: the reach is a pose of the sit said in the same clause ("sit at the desk with
  /// your hands on the keyboard"): it joins that step.
  absl::Status Reach(const Tokens& t, const std::string& c, bool in_pose = false);
  /// Hands of `sides` touch `part` of `o` while seated (UniHSI Table 7): the seat pairs stay in
  /// the step and the hand pairs have direction none.
  void AddSeatedReach(const CatalogObject& o, const std::string& part,
                      const std::vector<std::string>& sides, bool in_pose);
  absl::Status Tabletop(const Tokens& t, size_t b, const std::string& c);

  // ---- carrying (carry.cc)
  /// How a carry clause ends: kHold (carry/lift/pick up without a destination), kPutDown
  /// (put/place/drop without one: down where the carriers stand).
  enum class CarryDefault { kHold, kPutDown };
  /// Whether a clause's object and destination t[b, ...) make it a carry: the object (no part
  /// named) is held, or is carryable and goes to or beside (not onto) another object, or
  /// "here", or (`hold_ok`, for pick up / lift) has no destination.
  bool IsCarryClause(const Tokens& t, size_t b, bool hold_ok, const std::string& c);
  absl::Status Carry(const Tokens& t, size_t b, CarryDefault fallback, const std::string& c);
  absl::Status AddCarry(const CatalogObject& o, plan::CarryStep step, const std::string& text,
                        const std::string& c);
  core::StatusOr<std::vector<plan::Carrier>> Team(const CatalogObject& o, const std::string& c);

  const core::SceneCatalog& scene_;
  Viewer viewer_;
  Point2 pos_;
  Posture posture_ = Posture::kStand;
  const CatalogObject* on_ = nullptr;          // what the human sits or lies on
  const CatalogObject* focus_ = nullptr;       // the object last referred to ("it")
  int team_ = 0;                               // carriers asked for in this clause; 0: as needed
  const CatalogObject* held_ = nullptr;        // the object lifted and held ("pick up the box")
  std::vector<plan::Carrier> held_by_;         // who holds it
  std::optional<core::SceneCatalog> planned_;  // the scene as the carry steps so far leave it
  std::vector<StepDraft> steps_;
  int clause_ = 0;            // index of the clause being read
  bool sequenced_ = true;     // whether it followed "then" (see NextClause)
  bool attributive_ = false;  // the clause states a pose without a verb ("hands on knees")
  bool left_seat_ = false;    // the last step stood up from a seat or bed
};

}  // namespace simhuman::language::offline
