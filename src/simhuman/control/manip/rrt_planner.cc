#include "simhuman/control/manip/rrt_planner.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerStatus.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/goals/GoalStates.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "absl/strings/str_cat.h"
#include "simhuman/core/check.h"
#include "simhuman/core/rng.h"

namespace simhuman::control::manip {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;

// OMPL logs to the console by default; library code must not print. Process-wide, once.
void SilenceOmpl() {
  static std::once_flag once;
  std::call_once(once, [] {
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::msg::noOutputHandler();
  });
}

Eigen::VectorXd ToEigen(const ob::State* s, int n) {
  const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
  return Eigen::Map<const Eigen::VectorXd>(v, n);
}

void FromEigen(const Eigen::VectorXd& q, ob::State* s) {
  double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
  for (int i = 0; i < q.size(); ++i) v[i] = q[i];
}

// Uniform samples in the joint box from our own seeded generator (OMPL's generators take their
// seeds from one process-wide sequence, see the header).
class SeededSampler : public ob::StateSampler {
 public:
  SeededSampler(const ob::StateSpace* space, uint64_t seed, Eigen::VectorXd lower,
                Eigen::VectorXd upper)
      : ob::StateSampler(space), rng_(seed), lower_(std::move(lower)), upper_(std::move(upper)) {}

  void sampleUniform(ob::State* state) override {
    double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    for (int i = 0; i < lower_.size(); ++i) v[i] = Draw(lower_[i], upper_[i]);
  }
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    const double* c = near->as<ob::RealVectorStateSpace::StateType>()->values;
    for (int i = 0; i < lower_.size(); ++i) {
      v[i] = std::clamp(c[i] + Draw(-distance, distance), lower_[i], upper_[i]);
    }
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double stddev) override {
    double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    const double* c = mean->as<ob::RealVectorStateSpace::StateType>()->values;
    for (int i = 0; i < lower_.size(); ++i) {
      v[i] = std::clamp(c[i] + rng_.Normal(stddev), lower_[i], upper_[i]);
    }
  }

 private:
  double Draw(double lo, double hi) { return lo < hi ? rng_.Uniform(lo, hi) : lo; }

  core::Rng rng_;
  Eigen::VectorXd lower_, upper_;
};

// Straight motions checked with SegmentValid, so the planner and the shortcutting agree.
class SegmentMotionValidator : public ob::MotionValidator {
 public:
  SegmentMotionValidator(ob::SpaceInformation* si, int n, const ValidityFn* valid,
                         double resolution_rad)
      : ob::MotionValidator(si), n_(n), valid_fn_(valid), resolution_rad_(resolution_rad) {}

  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const bool ok = SegmentValid(ToEigen(s1, n_), ToEigen(s2, n_), *valid_fn_, resolution_rad_);
    ++(ok ? valid_ : invalid_);
    return ok;
  }

  // in order from s1, so that the last valid state is known
  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& last_valid) const override {
    const Eigen::VectorXd a = ToEigen(s1, n_);
    const Eigen::VectorXd delta = ToEigen(s2, n_) - a;
    const int steps =
        std::max(1, static_cast<int>(std::ceil(delta.cwiseAbs().maxCoeff() / resolution_rad_)));
    for (int k = 1; k <= steps; ++k) {
      if (!(*valid_fn_)(a + (static_cast<double>(k) / steps) * delta)) {
        last_valid.second = static_cast<double>(k - 1) / steps;
        if (last_valid.first != nullptr) FromEigen(a + last_valid.second * delta, last_valid.first);
        ++invalid_;
        return false;
      }
    }
    ++valid_;
    return true;
  }

 private:
  int n_;
  const ValidityFn* valid_fn_;
  double resolution_rad_;
};

// RRTConnect whose goal tree starts from every candidate goal at once. OMPL's RRTConnect takes
// a further goal from a GoalStates only when its goal tree has grown past twice the goals taken,
// so a first goal in a pocket (a valid state the tree cannot leave) would hide all the others.
class MultiRootRrtConnect : public og::RRTConnect {
 public:
  using og::RRTConnect::RRTConnect;

  ob::PlannerStatus solve(const ob::PlannerTerminationCondition& ptc) override {
    checkValidity();
    while (pis_.haveMoreGoalStates()) {
      const ob::State* st = pis_.nextGoal();
      if (st == nullptr) continue;  // an invalid goal (filtered before, so not expected)
      auto* motion = new Motion(si_);
      si_->copyState(motion->state, st);
      motion->root = motion->state;
      tGoal_->add(motion);
    }
    return og::RRTConnect::solve(ptc);
  }
};

std::string Num(double x) { return absl::StrCat(x); }

// one vector of joint values against the bounds: size, NaN, range
absl::Status CheckJoints(const Eigen::VectorXd& q, const std::string& what,
                         const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) {
  if (q.size() != lower.size()) {
    return absl::InvalidArgumentError(absl::StrCat("planner: ", what, " has ", q.size(),
                                                   " joints, the bounds have ", lower.size()));
  }
  for (int j = 0; j < q.size(); ++j) {
    if (std::isnan(q[j])) {
      return absl::InvalidArgumentError(absl::StrCat("planner: ", what, " joint ", j, " is NaN"));
    }
    if (!(q[j] >= lower[j] && q[j] <= upper[j])) {
      return absl::InvalidArgumentError(absl::StrCat("planner: ", what, " joint ", j, " = ",
                                                     Num(q[j]), " rad is outside its bounds [",
                                                     Num(lower[j]), ", ", Num(upper[j]), "]"));
    }
  }
  return absl::OkStatus();
}

absl::Status CheckInputs(const Eigen::VectorXd& start, const std::vector<Eigen::VectorXd>& goals,
                         const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) {
  if (lower.size() == 0) return absl::InvalidArgumentError("planner: no joints (empty bounds)");
  if (upper.size() != lower.size()) {
    return absl::InvalidArgumentError(absl::StrCat("planner: upper bounds have ", upper.size(),
                                                   " entries, lower bounds ", lower.size()));
  }
  for (int j = 0; j < lower.size(); ++j) {
    if (!std::isfinite(lower[j]) || !std::isfinite(upper[j]) || lower[j] > upper[j]) {
      return absl::InvalidArgumentError(absl::StrCat("planner: joint ", j, " bounds [",
                                                     Num(lower[j]), ", ", Num(upper[j]),
                                                     "] must be finite with lower <= upper"));
    }
  }
  if (goals.empty()) return absl::InvalidArgumentError("planner: no goals");
  SH_RETURN_IF_ERROR(CheckJoints(start, "start", lower, upper));
  for (size_t k = 0; k < goals.size(); ++k) {
    SH_RETURN_IF_ERROR(CheckJoints(goals[k], absl::StrCat("goal ", k), lower, upper));
  }
  return absl::OkStatus();
}

// What RRTConnect returned, in our terms.
struct RawPlan {
  JointPath path;
  double time_s = 0;
};

// The OMPL part: space, sampler, validity, problem, RRTConnect. Throws what OMPL throws.
core::StatusOr<RawPlan> RunRrtConnect(const Eigen::VectorXd& start,
                                      const std::vector<Eigen::VectorXd>& goals,
                                      const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                      const ValidityFn& valid, const PlannerOptions& options) {
  const int n = static_cast<int>(lower.size());
  auto space = std::make_shared<ob::RealVectorStateSpace>(n);
  ob::RealVectorBounds bounds(n);
  for (int j = 0; j < n; ++j) {
    bounds.setLow(j, lower[j]);
    bounds.setHigh(j, upper[j]);
  }
  space->setBounds(bounds);
  // each sampler the planner allocates gets its own stream of the run seed
  auto samplers = std::make_shared<uint64_t>(0);
  const uint64_t seed = options.seed;
  space->setStateSamplerAllocator([=](const ob::StateSpace* s) -> ob::StateSamplerPtr {
    return std::make_shared<SeededSampler>(s, core::DeriveSeed(seed, 0, (*samplers)++), lower,
                                           upper);
  });

  // every check counts against the check budget
  int64_t checks = 0;
  const ValidityFn counted = [&](const Eigen::VectorXd& q) {
    ++checks;
    return valid(q);
  };
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker([&](const ob::State* s) { return counted(ToEigen(s, n)); });
  si->setMotionValidator(
      std::make_shared<SegmentMotionValidator>(si.get(), n, &counted, options.resolution_rad));
  si->setup();

  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  ob::State* state = si->allocState();
  FromEigen(start, state);
  pdef->addStartState(state);
  auto goal_states = std::make_shared<ob::GoalStates>(si);
  for (const Eigen::VectorXd& g : goals) {
    FromEigen(g, state);
    goal_states->addState(state);
  }
  si->freeState(state);
  pdef->setGoal(goal_states);

  auto planner = std::make_shared<MultiRootRrtConnect>(si);
  if (options.range_rad > 0) planner->setRange(options.range_rad);
  planner->setProblemDefinition(pdef);
  planner->setup();

  const Clock::time_point t0 = Clock::now();
  const int64_t max_checks = options.max_validity_checks;
  const ob::PlannerTerminationCondition out_of_checks(
      [&checks, max_checks] { return max_checks > 0 && checks >= max_checks; });
  const ob::PlannerStatus status = planner->solve(ob::plannerOrTerminationCondition(
      ob::timedPlannerTerminationCondition(options.time_limit_s), out_of_checks));
  RawPlan raw;
  raw.time_s = std::chrono::duration<double>(Clock::now() - t0).count();
  if (status == ob::PlannerStatus::TIMEOUT || status == ob::PlannerStatus::APPROXIMATE_SOLUTION) {
    const std::string budget = max_checks > 0 && checks >= max_checks
                                   ? absl::StrCat(max_checks, " validity checks")
                                   : Num(options.time_limit_s) + " s";
    return absl::NotFoundError(absl::StrCat("planner: no collision-free path within ", budget, " (",
                                            goals.size(), " valid goal(s))"));
  }
  if (status != ob::PlannerStatus::EXACT_SOLUTION || !pdef->hasExactSolution()) {
    return absl::InternalError("planner: RRTConnect returned '" + status.asString() + "'");
  }
  const auto* path = pdef->getSolutionPath()->as<og::PathGeometric>();
  for (std::size_t i = 0; i < path->getStateCount(); ++i) {
    raw.path.waypoints.push_back(ToEigen(path->getState(static_cast<unsigned int>(i)), n));
  }
  return raw;
}

}  // namespace

absl::Status PlannerOptions::Validate() const {
  if (!(time_limit_s > 0 && time_limit_s <= 3600)) {
    return absl::InvalidArgumentError("planner: time_limit_s = " + Num(time_limit_s) +
                                      " must be in (0, 3600] s");
  }
  if (!(resolution_rad > 0 && resolution_rad <= 1.0)) {
    return absl::InvalidArgumentError("planner: resolution_rad = " + Num(resolution_rad) +
                                      " must be in (0, 1] rad");
  }
  if (max_validity_checks < 0) {
    return absl::InvalidArgumentError(absl::StrCat(
        "planner: max_validity_checks = ", max_validity_checks, " must be >= 0 (0: no budget)"));
  }
  if (shortcut_iterations < 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("planner: shortcut_iterations = ", shortcut_iterations, " must be >= 0"));
  }
  if (!(range_rad >= 0 && std::isfinite(range_rad))) {
    return absl::InvalidArgumentError("planner: range_rad = " + Num(range_rad) +
                                      " must be finite and >= 0 (0: OMPL's default)");
  }
  if (!(start_escape_rad >= 0 && std::isfinite(start_escape_rad))) {
    return absl::InvalidArgumentError("planner: start_escape_rad = " + Num(start_escape_rad) +
                                      " must be finite and >= 0");
  }
  return absl::OkStatus();
}

core::StatusOr<PlanResult> PlanJointPath(const Eigen::VectorXd& start,
                                         const std::vector<Eigen::VectorXd>& goals,
                                         const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                         const ValidityFn& valid, const PlannerOptions& options) {
  SH_RETURN_IF_ERROR(options.Validate());
  SH_RETURN_IF_ERROR(CheckInputs(start, goals, lower, upper));
  SH_CHECK(static_cast<bool>(valid), "PlanJointPath needs a validity function");
  SilenceOmpl();
  PlanResult result;
  try {
    // an invalid start may leave through a small ball around it when the caller allows it
    ValidityFn checker = valid;
    if (!valid(start)) {
      if (options.start_escape_rad <= 0) {
        return absl::InvalidArgumentError(
            "planner: the start is invalid (in collision); set start_escape_rad to let the path "
            "leave a marginal collision");
      }
      const double radius = options.start_escape_rad;
      checker = [start, radius, &valid](const Eigen::VectorXd& q) {
        return (q - start).norm() <= radius || valid(q);
      };
      result.start_escaped = true;
    }
    // candidate goals the checker accepts, with their indices in `goals`
    std::vector<Eigen::VectorXd> usable;
    std::vector<int> usable_index;
    for (size_t k = 0; k < goals.size(); ++k) {
      if (checker(goals[k])) {
        usable.push_back(goals[k]);
        usable_index.push_back(static_cast<int>(k));
      }
    }
    if (usable.empty()) {
      return absl::InvalidArgumentError(
          absl::StrCat("planner: all ", goals.size(), " goal(s) are invalid (in collision)"));
    }
    for (size_t k = 0; k < usable.size(); ++k) {
      if ((usable[k] - start).norm() == 0) {  // already there
        result.path.waypoints = {start, usable[k]};
        result.goal_index = usable_index[k];
        result.raw_waypoints = 2;
        return result;
      }
    }

    SH_ASSIGN_OR_RETURN(RawPlan raw, RunRrtConnect(start, usable, lower, upper, checker, options));
    result.planning_time_s = raw.time_s;
    result.raw_waypoints = raw.path.size();
    result.raw_length_rad = raw.path.Length();
    SH_CHECK(raw.path.size() >= 2, "RRTConnect returned a path of fewer than two states");
    // the path ends on a copy of one goal state: find which
    int best = 0;
    for (size_t k = 1; k < usable.size(); ++k) {
      if ((usable[k] - raw.path.waypoints.back()).squaredNorm() <
          (usable[best] - raw.path.waypoints.back()).squaredNorm()) {
        best = static_cast<int>(k);
      }
    }
    result.goal_index = usable_index[best];
    raw.path.waypoints.front() = start;
    raw.path.waypoints.back() = usable[best];

    if (options.simplify) {
      const Clock::time_point t0 = Clock::now();
      ShortcutOptions shortcut;
      shortcut.iterations = options.shortcut_iterations;
      shortcut.resolution_rad = options.resolution_rad;
      core::Rng rng(core::DeriveSeed(options.seed, 1));
      SH_ASSIGN_OR_RETURN(result.path, ShortcutPath(raw.path, checker, shortcut, rng));
      result.simplify_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
    } else {
      result.path = std::move(raw.path);
    }
  } catch (const std::exception& e) {
    return absl::InternalError(absl::StrCat("planner: OMPL failed: ", e.what()));
  }
  return result;
}

}  // namespace simhuman::control::manip
