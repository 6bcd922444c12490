#pragma once
/// Collision-free joint paths for the arm's reach and transport (DASH Appendix A.2.2): OMPL's
/// RRTConnect (BiRRT, Kuffner and LaValle 2000) in a box of joint bounds, towards one of several
/// candidate goals (the IK solutions), followed by our random shortcutting (joint_path.h).
/// Every valid candidate goal is a root of the backward tree from the start of the search (OMPL
/// alone would take a further goal only once the tree of the first one grows, so a first goal in
/// a pocket would hide the others).
/// OMPL stays inside rrt_planner.cc; this header does not include it.
///
/// Determinism: OMPL seeds every ompl::RNG it constructs from one process-wide seed sequence.
/// ompl::RNG::setSeed sets that sequence's seed; in OMPL 1.5.2 (RandomNumbers.cpp), once any RNG
/// exists a further call logs "Random number generation already started" and only re-seeds the
/// sequence for RNGs constructed later, so per-plan seeds through it would be process-global,
/// racy between threads and dependent on what was constructed before. Instead the planner
/// installs its own state sampler (StateSpace::setStateSamplerAllocator) drawing from a
/// core::Rng seeded with PlannerOptions::seed. In OMPL 1.5.2 RRTConnect::solve draws random
/// numbers only from that sampler (its own rng_ member is unused there), its nearest-neighbour
/// structure (GNAT) answers exact queries (its random pivots do not change the answers), and
/// the goals become tree roots in their given order. OMPL's PathSimplifier has a private,
/// unseedable generator, so shortcutting is ours (seeded too). Same inputs and seed, and a plan
/// found within the time limit, give the same path whatever ran before in the process (a plan cut
/// by the time limit is timing-dependent).
///
/// Logging: OMPL's console output is switched off process-wide on first use
/// (ompl::msg::setLogLevel(LOG_NONE) and no output handler): library code does not print.
///
/// Thread-safety: PlanJointPath may run concurrently on several threads with separate validity
/// functions; each call calls its validity function only from the calling thread.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "simhuman/control/manip/joint_path.h"
#include "simhuman/core/status.h"

namespace simhuman::control::manip {

/// Planner settings. Units: seconds and radians (joint-space distances are Euclidean).
struct PlannerOptions {
  double time_limit_s = 1.0;  ///< wall-clock budget of the RRTConnect search
  /// A budget of state-validity checks for the search (0: none). When it binds before the
  /// clock, the outcome does not depend on the machine's speed or load: the same inputs and seed
  /// find the same path or fail alike (a wall-clock budget fails more plans on a busy machine).
  int64_t max_validity_checks = 0;
  uint64_t seed = 1;  ///< sampler and shortcut seed
  /// straight motions are checked so that consecutive checked states differ by at most this
  /// much in every joint (see SegmentValid)
  double resolution_rad = 0.02;
  bool simplify = true;  ///< shortcut the raw RRTConnect path (ShortcutPath)
  /// random shortcut attempts when simplifying. Each costs up to (its length / resolution_rad)
  /// validity calls: measured on the seated humanoid's 7-DoF arm reaching over a table (3 IK
  /// goals, ~89 us per full-model collision check), 0 / 50 / 100 / 200 attempts took 13 / 105
  /// / 197 / 326 ms and left paths of 4.85 / 2.72 / 2.48 / 2.32 rad (raw 6.21 rad)
  int shortcut_iterations = 50;
  /// RRTConnect's extension length; 0: OMPL's default (20 % of the bound box's diagonal)
  double range_rad = 0.0;
  /// When > 0 and the start is invalid (an arm holding an object that touches the table), the
  /// states within this Euclidean joint distance of the start count as valid, so the path may
  /// leave the start through the marginal collision. 0: an invalid start is an error.
  double start_escape_rad = 0.0;

  /// InvalidArgument naming the field when out of range.
  absl::Status Validate() const;
};

/// A found path and how it was found.
struct PlanResult {
  JointPath path;              ///< from the start to goals[goal_index], both exactly
  int goal_index = -1;         ///< which of the candidate goals the path reaches
  double planning_time_s = 0;  ///< RRTConnect search time
  double simplify_time_s = 0;  ///< shortcutting time
  int raw_waypoints = 0;       ///< waypoints of RRTConnect's path before shortcutting
  double raw_length_rad = 0;   ///< its length
  bool start_escaped = false;  ///< the start was invalid and start_escape_rad let it leave
};

/// Plans a path from `start` to any of `goals` inside the joint box [lower, upper] (rad, one
/// entry per joint) through states where `valid` holds, with straight motions checked at
/// options.resolution_rad. Goals for which `valid` is false are skipped. (One goal: `{goal}`.)
/// Errors:
///  - InvalidArgument: bad options; no goals; sizes that differ from lower.size() (naming the
///    vector); lower > upper or non-finite bounds, NaN, or start/goal values outside the bounds
///    (naming the joint, the value and the bounds); an invalid start without start_escape_rad;
///    every goal invalid.
///  - NotFound: "no collision-free path within X s" (or "within N validity checks") when the
///    search runs out of its budget.
///  - Internal: an exception from OMPL (its message).
core::StatusOr<PlanResult> PlanJointPath(const Eigen::VectorXd& start,
                                         const std::vector<Eigen::VectorXd>& goals,
                                         const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                         const ValidityFn& valid,
                                         const PlannerOptions& options = {});

}  // namespace simhuman::control::manip
