#include "simhuman/plan/metrics.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "simhuman/core/check.h"
#include "simhuman/core/footprint.h"

namespace simhuman::plan {
namespace {

// slack when comparing differences of accumulated tick times against hold_s
constexpr double kTimeSlackS = 1e-9;
// alternating-projection rounds when measuring the distance between two parts
constexpr int kObjectPairIterations = 8;

absl::Status CheckField(bool ok, const char* name, double value, const char* rule) {
  if (ok && std::isfinite(value)) return absl::OkStatus();
  return absl::InvalidArgumentError(std::string(name) + " = " + std::to_string(value) +
                                    " is invalid: must be finite and " + rule);
}

// unit horizontal vector of `v`, or zero when v has no horizontal component
Eigen::Vector3d Horizontal(const Eigen::Vector3d& v) {
  Eigen::Vector3d h(v.x(), v.y(), 0.0);
  double n = h.norm();
  return n > 1e-12 ? Eigen::Vector3d(h / n) : Eigen::Vector3d::Zero();
}

double Clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

// UniHSI's rules (Eq. 7-8) and reward/error for a pair whose distance and direction agreement
// are already in `e` (joint-to-part and part-to-part pairs alike)
void ScoreByType(ContactType type, const PairParams& params, PairEval* e) {
  const double decay = std::exp(-params.w_dk_per_m * e->distance_m);
  switch (type) {
    case ContactType::kContact:
      e->satisfied =
          e->distance_m < params.contact_threshold_m && e->direction_dot > params.direction_dot_min;
      e->reward = Clamp01(params.w_dis * decay + params.w_dir * std::min(e->direction_dot, 0.0));
      e->has_error = true;
      e->error_m = e->distance_m;
      break;
    case ContactType::kNotContact:
      e->satisfied = e->distance_m > params.contact_threshold_m;
      e->reward = Clamp01(1.0 - decay);
      e->has_error = true;
      e->error_m = std::max(params.not_contact_error_m - e->distance_m, 0.0);
      break;
    case ContactType::kNotCare:
      e->satisfied = true;
      e->reward = 1.0;
      break;
  }
}

PairEval EvaluateGetClose(const ContactPair& pair, const core::CatalogObject& object,
                          const BodyPoints& body, const PairParams& params) {
  PairEval e;
  const Eigen::Vector3d stand = StandPoint(object, pair.direction, params.stand_off_m);
  const Eigen::Vector3d& pelvis = body.at(core::BodyJoint::kPelvis);
  e.target_world = stand;
  e.d_vec = Eigen::Vector3d(stand.x() - pelvis.x(), stand.y() - pelvis.y(), 0.0);
  e.distance_m = e.d_vec.norm();
  const Eigen::Vector3d want = -DirectionVector(pair.direction, object.pose);
  const Eigen::Vector3d facing = Horizontal(body.facing_world);
  e.direction_dot = std::clamp(facing.dot(want), -1.0, 1.0);  // 0 when facing is degenerate
  e.satisfied = e.distance_m < params.get_close_radius_m &&
                e.direction_dot >= std::cos(params.get_close_facing_tol_rad);
  e.reward = Clamp01(params.w_dis * std::exp(-params.w_dk_per_m * e.distance_m) +
                     params.w_dir * std::min(e.direction_dot, 0.0));
  return e;
}

// the part of `object` called `name` (canonical first, then FindPart's rule)
const core::CatalogPart* PartNamed(const core::CatalogObject& object, const std::string& name) {
  for (const core::CatalogPart& candidate : object.parts) {
    if (candidate.name == name) return &candidate;
  }
  return object.FindPart(name);
}

// centre of the world bounds of a part's shapes (a starting point for the closest-point search)
Eigen::Vector3d PartCentre(const core::CatalogPart& part, const core::Pose& pose) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const core::Shape& shape : part.shapes) sum += pose.Apply(shape.pose.pos);
  return sum / static_cast<double>(std::max<size_t>(part.shapes.size(), 1));
}

}  // namespace

PairEval EvaluateObjectPair(const ContactPair& pair, const core::SceneCatalog& scene,
                            const PairParams& params) {
  SH_CHECK(pair.IsObjectPair(), "EvaluateObjectPair: not an object-object pair");
  const core::CatalogObject* object = scene.Find(pair.object);
  const core::CatalogObject* subject = scene.Find(*pair.subject_object);
  SH_CHECK(object != nullptr && subject != nullptr,
           "EvaluateObjectPair: object not in the scene (validate the plan first)");
  const core::CatalogPart* part = PartNamed(*object, pair.part);
  const core::CatalogPart* subject_part = PartNamed(*subject, pair.subject_part);
  SH_CHECK(part != nullptr && subject_part != nullptr,
           "EvaluateObjectPair: part not in the object (validate the plan first)");
  // closest points of the two parts by alternating projection (exact for convex parts, a
  // close upper bound otherwise)
  Eigen::Vector3d on_subject = PartCentre(*subject_part, subject->pose);
  Eigen::Vector3d on_object = core::NearestPointOnShapes(part->shapes, object->pose, on_subject);
  for (int i = 0; i < kObjectPairIterations; ++i) {
    on_subject = core::NearestPointOnShapes(subject_part->shapes, subject->pose, on_object);
    on_object = core::NearestPointOnShapes(part->shapes, object->pose, on_subject);
  }
  PairEval e;
  e.target_world = on_object;
  e.d_vec = on_object - on_subject;
  e.distance_m = e.d_vec.norm();
  // where the subject lies relative to the object part: the subject's centre seen from the
  // object part's nearest point (the closest points coincide once the parts touch)
  const Eigen::Vector3d d_hat = DirectionVector(pair.direction, object->pose);
  const Eigen::Vector3d centre = PartCentre(*subject_part, subject->pose);
  const Eigen::Vector3d from = core::NearestPointOnShapes(part->shapes, object->pose, centre);
  const Eigen::Vector3d rel = centre - from;
  if (pair.direction == Direction::kNone || rel.norm() < params.direction_epsilon_m) {
    e.direction_dot = 1.0;
  } else {
    e.direction_dot = std::clamp(rel.normalized().dot(d_hat), -1.0, 1.0);
  }
  ScoreByType(pair.type, params, &e);
  return e;
}

absl::Status PairParams::Validate() const {
  SH_RETURN_IF_ERROR(
      CheckField(contact_threshold_m >= 0, "contact_threshold_m", contact_threshold_m, ">= 0"));
  SH_RETURN_IF_ERROR(CheckField(direction_dot_min >= -1 && direction_dot_min <= 1,
                                "direction_dot_min", direction_dot_min, "in [-1, 1]"));
  SH_RETURN_IF_ERROR(
      CheckField(direction_epsilon_m >= 0, "direction_epsilon_m", direction_epsilon_m, ">= 0"));
  SH_RETURN_IF_ERROR(CheckField(w_dis >= 0, "w_dis", w_dis, ">= 0"));
  SH_RETURN_IF_ERROR(CheckField(w_dir >= 0, "w_dir", w_dir, ">= 0"));
  SH_RETURN_IF_ERROR(CheckField(w_dk_per_m > 0, "w_dk_per_m", w_dk_per_m, "> 0"));
  SH_RETURN_IF_ERROR(
      CheckField(not_contact_error_m >= 0, "not_contact_error_m", not_contact_error_m, ">= 0"));
  SH_RETURN_IF_ERROR(
      CheckField(get_close_radius_m > 0, "get_close_radius_m", get_close_radius_m, "> 0"));
  SH_RETURN_IF_ERROR(CheckField(get_close_facing_tol_rad >= 0 && get_close_facing_tol_rad <= M_PI,
                                "get_close_facing_tol_rad", get_close_facing_tol_rad,
                                "in [0, pi]"));
  SH_RETURN_IF_ERROR(CheckField(stand_off_m >= 0, "stand_off_m", stand_off_m, ">= 0"));
  SH_RETURN_IF_ERROR(
      CheckField(adaptive_weight_eps > 0, "adaptive_weight_eps", adaptive_weight_eps, "> 0"));
  return absl::OkStatus();
}

double ObjectYaw(const core::Pose& object_pose) { return core::PoseYaw(object_pose); }

Eigen::Vector3d DirectionVector(Direction d, const core::Pose& object_pose) {
  const double yaw = ObjectYaw(object_pose);
  const Eigen::Vector3d front(std::cos(yaw), std::sin(yaw), 0.0);
  const Eigen::Vector3d left(-std::sin(yaw), std::cos(yaw), 0.0);
  switch (d) {
    case Direction::kUp:
      return Eigen::Vector3d::UnitZ();
    case Direction::kDown:
      return -Eigen::Vector3d::UnitZ();
    case Direction::kFront:
      return front;
    case Direction::kBack:
      return -front;
    case Direction::kLeft:
      return left;
    case Direction::kRight:
      return -left;
    case Direction::kNone:
      return Eigen::Vector3d::Zero();
  }
  return Eigen::Vector3d::Zero();
}

Eigen::Vector3d StandPoint(const core::CatalogObject& object, Direction side, double stand_off_m) {
  SH_CHECK(IsSideDirection(side), "StandPoint needs front, back, left or right");
  SH_CHECK(!object.shapes.empty(), "StandPoint needs an object with shapes");
  const auto [lo, hi] = object.LocalBounds();
  const Eigen::Vector2d centre = 0.5 * (lo.head<2>() + hi.head<2>());
  Eigen::Vector2d local = centre;
  switch (side) {
    case Direction::kFront:
      local.x() = hi.x() + stand_off_m;
      break;
    case Direction::kBack:
      local.x() = lo.x() - stand_off_m;
      break;
    case Direction::kLeft:
      local.y() = hi.y() + stand_off_m;
      break;
    case Direction::kRight:
      local.y() = lo.y() - stand_off_m;
      break;
    default:
      break;
  }
  const double yaw = ObjectYaw(object.pose);
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {object.pose.pos.x() + c * local.x() - s * local.y(),
          object.pose.pos.y() + s * local.x() + c * local.y(), 0.0};
}

double StandFacingYaw(const core::CatalogObject& object, Direction side) {
  SH_CHECK(IsSideDirection(side), "StandFacingYaw needs front, back, left or right");
  const Eigen::Vector3d want = -DirectionVector(side, object.pose);
  return std::atan2(want.y(), want.x());
}

BellyTouch BellyPoint(core::Span<const Eigen::Vector3d> pts) {
  SH_CHECK(pts.size() >= core::kNumBodyJoints, "BellyPoint needs the 15 standard body points");
  auto at = [&](core::BodyJoint j) -> const Eigen::Vector3d& { return pts[static_cast<int>(j)]; };
  const Eigen::Vector3d hips =
      0.5 * (at(core::BodyJoint::kLeftHip) + at(core::BodyJoint::kRightHip));
  Eigen::Vector3d left = at(core::BodyJoint::kLeftHip) - at(core::BodyJoint::kRightHip);
  const double spacing = left.norm();
  BellyTouch out;
  out.pos = hips;
  if (spacing < 1e-9) return out;
  left /= spacing;
  Eigen::Vector3d up = hips - at(core::BodyJoint::kPelvis);
  up -= up.dot(left) * left;
  if (up.norm() < 1e-9) return out;
  up.normalize();
  const double s = spacing / 0.17;
  out.normal = left.cross(up);
  out.pos = hips + s * (0.085 * out.normal + 0.18 * up);
  return out;
}

bool TouchesBelly(const ContactPair& pair, const PairParams& params) {
  return params.hand_on_pelvis_at_belly && pair.part_joint == core::BodyJoint::kPelvis &&
         (pair.joint == core::BodyJoint::kLeftHand || pair.joint == core::BodyJoint::kRightHand);
}

PairEval EvaluatePair(const ContactPair& pair, const core::SceneCatalog& scene,
                      const std::vector<BodyPoints>& agents, const PairParams& params) {
  SH_CHECK(pair.agent >= 0 && pair.agent < static_cast<int>(agents.size()),
           "EvaluatePair: agent index out of range of the body points");
  const core::CatalogObject* object = scene.Find(pair.object);
  SH_CHECK(object != nullptr, "EvaluatePair: object not in the scene (validate the plan first)");
  const BodyPoints& body = agents[pair.agent];
  if (pair.IsGetClose()) return EvaluateGetClose(pair, *object, body, params);
  if (pair.IsObjectPair()) return EvaluateObjectPair(pair, scene, params);
  SH_CHECK(pair.joint.has_value(), "EvaluatePair: pair without a joint");

  PairEval e;
  const Eigen::Vector3d& v_j = body.at(*pair.joint);
  if (TouchesBelly(pair, params)) {
    e.target_world = BellyPoint(body.pos_world).pos;
  } else if (pair.part_joint) {
    e.target_world = body.at(*pair.part_joint);
  } else {
    // grounding leaves the canonical name; FindPart covers chains built in code
    const core::CatalogPart* part = nullptr;
    for (const core::CatalogPart& candidate : object->parts) {
      if (candidate.name == pair.part) part = &candidate;
    }
    if (part == nullptr) part = object->FindPart(pair.part);
    SH_CHECK(part != nullptr, "EvaluatePair: part not in the object (validate the plan first)");
    e.target_world = core::NearestPointOnShapes(part->shapes, object->pose, v_j);
  }
  e.d_vec = e.target_world - v_j;
  e.distance_m = e.d_vec.norm();

  // direction agreement: where the joint lies relative to the target
  const Eigen::Vector3d d_hat = DirectionVector(pair.direction, object->pose);
  if (pair.direction == Direction::kNone || e.distance_m < params.direction_epsilon_m) {
    e.direction_dot = 1.0;
  } else {
    e.direction_dot = std::clamp((-e.d_vec / e.distance_m).dot(d_hat), -1.0, 1.0);
  }

  ScoreByType(pair.type, params, &e);
  return e;
}

std::vector<double> AdaptiveWeights(const std::vector<double>& rewards, double eps) {
  double sum = 0.0;
  for (double r : rewards) sum += r;
  const double denom = static_cast<double>(rewards.size()) - sum + eps;
  std::vector<double> w;
  w.reserve(rewards.size());
  for (double r : rewards) w.push_back((1.0 - r) / denom);
  return w;
}

StepEval EvaluateStep(const ContactStep& step, const core::SceneCatalog& scene,
                      const std::vector<BodyPoints>& agents, const PairParams& params) {
  StepEval out;
  out.complete = true;
  std::vector<double> rewards;
  for (const ContactPair& pair : step.pairs) {
    out.pairs.push_back(EvaluatePair(pair, scene, agents, params));
    rewards.push_back(out.pairs.back().reward);
    out.complete = out.complete && out.pairs.back().satisfied;
  }
  out.weights = AdaptiveWeights(rewards, params.adaptive_weight_eps);
  for (size_t k = 0; k < rewards.size(); ++k) out.reward += out.weights[k] * rewards[k];
  // a carry step with a destination completes when the object is down there and let go
  if (step.carry && step.carry->goal) {
    const core::CatalogObject* obj = scene.Find(step.carry->object);
    bool released = true;
    for (const PairEval& e : out.pairs) released = released && !e.satisfied;
    out.complete = obj && released && CarriedObjectAtGoal(obj->pose, *step.carry->goal);
  }
  return out;
}

bool CarriedObjectAtGoal(const core::Pose& object, const core::Pose& goal) {
  return (object.pos - goal.pos).head<2>().norm() < kCarryGoalRadiusM &&
         std::abs(object.pos.z() - goal.pos.z()) < kCarryGoalHeightTolM;
}

absl::Status TrackerParams::Validate() const {
  SH_RETURN_IF_ERROR(CheckField(hold_s >= 0, "hold_s", hold_s, ">= 0"));
  SH_RETURN_IF_ERROR(
      CheckField(budget_s_per_step > 0, "budget_s_per_step", budget_s_per_step, "> 0"));
  return absl::OkStatus();
}

StepTracker::StepTracker(const ContactChain& chain, const TrackerParams& params) : params_(params) {
  SH_CHECK(params.Validate().ok(), "StepTracker: invalid TrackerParams");
  SH_CHECK(!chain.steps.empty(), "StepTracker: empty chain");
  for (const ContactStep& step : chain.steps) {
    SH_CHECK(!step.pairs.empty(), "StepTracker: empty step");
    pairs_per_step_.push_back(static_cast<int>(step.pairs.size()));
  }
  records_.resize(chain.steps.size());
  budget_s_ = params.budget_s_per_step * static_cast<double>(chain.steps.size());
}

void StepTracker::RecordErrors(int step, const StepEval& eval) {
  StepRecord& r = records_[step];
  r.errors_m.clear();
  for (const PairEval& p : eval.pairs) {
    if (p.has_error) r.errors_m.push_back(p.error_m);
  }
  r.errors_recorded = true;
}

void StepTracker::Update(double time_s, const StepEval& eval) {
  SH_CHECK(std::isfinite(time_s), "StepTracker::Update: time is not finite");
  SH_CHECK(!has_time_ || time_s >= last_time_s_, "StepTracker::Update: time went backwards");
  has_time_ = true;
  last_time_s_ = time_s;
  if (finished_) return;
  SH_CHECK(static_cast<int>(eval.pairs.size()) == pairs_per_step_[current_],
           "StepTracker::Update: evaluation is not of the current step");

  // out of time: the step being worked on keeps the errors of its last evaluation in budget
  if (time_s > budget_s_) {
    RecordErrors(current_, last_eval_ ? *last_eval_ : eval);
    timed_out_ = true;
    finished_ = true;
    return;
  }
  last_eval_ = eval;

  if (!eval.complete) {
    complete_since_s_.reset();
    return;
  }
  if (!complete_since_s_) complete_since_s_ = time_s;
  if (time_s - *complete_since_s_ + kTimeSlackS < params_.hold_s) return;

  StepRecord& r = records_[current_];
  r.completed = true;
  r.completion_time_s = time_s;
  RecordErrors(current_, eval);
  ++current_;
  complete_since_s_.reset();
  last_eval_.reset();
  if (done()) finished_ = true;
}

void StepTracker::Finish() {
  if (finished_) return;
  if (last_eval_) RecordErrors(current_, *last_eval_);
  finished_ = true;
}

std::vector<double> StepTracker::completion_times_s() const {
  std::vector<double> out;
  for (const StepRecord& r : records_) {
    if (r.completed) out.push_back(r.completion_time_s);
  }
  return out;
}

std::optional<double> StepTracker::contact_error_m() const {
  double sum = 0.0;
  int n = 0;
  for (const StepRecord& r : records_) {
    for (double e : r.errors_m) {
      sum += e;
      ++n;
    }
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

int StepTracker::num_error_pairs() const {
  int n = 0;
  for (const StepRecord& r : records_) n += static_cast<int>(r.errors_m.size());
  return n;
}

}  // namespace simhuman::plan
