#pragma once
/// DASH's pick-and-place pipeline for one seated human's right arm and hand: reach (planned),
/// grasp (a closed-loop policy), lift and transport (planned, the grip held by DASH's
/// tracking-error trick), place or stack (lower until the object bears on its support), release,
/// retract, then wait for the object to settle. Each stage reports its own failure, so a
/// benchmark can tell plan failures from grasp misses, drops in transport and topples at place.
///
/// The grasp policy is given as a function (the pipeline stays Torch-free); its observations and
/// actions are grasp_task.h's.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "simhuman/control/manip/carry_over.h"
#include "simhuman/control/manip/grasp_task.h"
#include "simhuman/control/manip/place_task.h"
#include "simhuman/control/manip/reach.h"
#include "simhuman/core/status.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control::manip {

/// One policy step: kGraspObsDim observations in, kGraspActDim actions out.
using GraspPolicyFn = std::function<void(const float* obs, float* action)>;

/// How the controllers see the moved object: its centre (of mass), base centre and up axis
/// (world), and for a box the yaw of a face normal.
struct ObjectView {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double yaw_rad = 0;
  /// An estimate (a camera's) rather than the simulation's state: controllers that would follow
  /// the object's every move (the grasp's palm while it presses) go by touch instead.
  bool estimated = false;
};

/// What to move and where.
struct TabletopGoal {
  int object_body = -1;
  GraspShape shape = GraspShape::kBox;
  double half_width_m = 0.04;   ///< the object's half width (sphere: radius)
  double height_m = 0.15;       ///< its height (sphere: diameter)
  Eigen::Vector3d planned_pos;  ///< its base centre as the plan believes (world)
  /// Where its base centre must end (world): a place location on the table, or the top centre
  /// of the object it is stacked on.
  Eigen::Vector3d target;
  int support_body = -1;  ///< the body it is stacked on (-1: the table)
  /// Where the hand grips it, above its base; < 0: TabletopOptions' rule (GripHeightM).
  double grip_height_m = -1;
  /// Success needs its centre of mass at least this far above the target's z (DASH: 5 cm; a
  /// cone's stands lower than that on its own base).
  double min_com_above_target_m = 0.05;
  /// How the controllers see the object while they work (the reach's box faces, the scripted
  /// grasp's approach, transport, the alignment over the target). Empty: the simulation's own
  /// state (ground truth); the vision module supplies its delayed camera estimates
  /// (eval/tabletop_vision.h). Outcome checks (dropped, lifted, at rest) always read the
  /// simulation.
  /// `held`: the object is in the hand (transport, alignment) rather than on the table (reach,
  /// grasp).
  std::function<ObjectView(const mjData* d, bool held)> observe;
};

/// `goal.observe(d, held)` when set, else the object's state in `d` (centre of mass, body origin
/// at its base, body z axis, yaw of its body x axis).
ObjectView ObserveObject(const TabletopGoal& goal, const mjData* d, bool held);

/// The seated human's raise over the table's edge (TabletopOptions::raise_via_rad): the arm
/// out a little, then the elbow drawn back and bent with the wrist extended, the hand rising in
/// front of the shoulder.
std::vector<std::vector<double>> SeatedRaiseViaRad();

/// Settings of RunTabletop.
struct TabletopOptions {
  ArmMotionOptions motion;
  TrackerGains tracker;      ///< the arm's tracking (reach, lift, transport, place, retract)
  int approach_angles = 16;  ///< DASH's theta samples around a round object
  double box_face_spread_rad =
      0.15;  ///< a box: each face's normal and 1 and 2 times this either side
  /// The reach ends with the palm this far from the object. 5 cm (session 34 and before) left
  /// the scripted grasp's approach a longer run at the object: 3-4 cm placed 234 of 272 boxes
  /// and cylinders of the suite's episodes 0-399 against 227 (docs/BENCHMARKS.md, session 34)
  double pregrasp_gap_m = 0.04;
  /// The palm's centre this far short of the object's axis along the fingers, and for a wide
  /// object so far that its near side stays within `palm_behind_margin_m` of the palm's centre
  /// (clear of the thumb's C)
  double palm_behind_m = 0.025;
  double palm_behind_margin_m = 0.005;
  int grasp_policy_steps = 60;  ///< 1.5 s at 40 Hz
  /// The widest object (across where the palm holds it: a box's side, a cylinder's or sphere's
  /// diameter) the hand is asked to close around; a wider one ends the run before anything moves
  /// ("too wide for the hand"). From `simhuman run` on tabletop_demo with one object widened
  /// (session 37): a 10 cm cylinder (DASH's widest) was stacked, a 12 cm one lifted and dropped
  /// in transport, 14 and 16 cm ones never closed around.
  double max_grip_width_m = 0.12;
  /// Grasp attempts: after a miss (the object does not rise with the hand) the hand opens,
  /// backs away, and, when the object still stands upright on its support where the controllers
  /// see it, reaches for it again from there with a fresh grasp policy, as a person tries again.
  /// 1: no second try (DASH).
  int grasp_attempts = 2;
  /// The palm's centre at this fraction of a box's or cylinder's height (a sphere: its centre),
  /// at most `grip_max_m` above its base
  double grip_height_frac = 0.5;
  double grip_max_m = 0.09;
  double grip_min_m = 0.06;  ///< the palm (9.6 cm wide) clears the table
  /// When no arm pose or path reaches the grip height even at the furthest lean, the palm's
  /// centre goes this far below the object's top instead (the palm's upper edge near the top)
  double grip_below_top_m = 0.045;
  /// A sphere is taken from above (TopGraspPose, the claw pre-shape): the palm comes down on its
  /// top, which the table holds still, and the fingers close over its far side with the thumb
  /// behind it. Off by default: on 21 sphere tasks it lifted 6 balls (the side grasp none, a
  /// ball rolls away from the first touch) but placed none either, and added plan failures
  /// (docs/BENCHMARKS.md, issue 15 session 17).
  bool sphere_top_grasp = false;
  double top_standoff_m = 0.04;      ///< the reach ends with the palm this far above the top
  double top_palm_behind_m = 0.035;  ///< the palm point this far back from the top (along fingers)
  int top_yaws = 12;                 ///< finger directions tried around the vertical
  double lift_m = 0.12;              ///< straight up after the grasp
  /// The object's base this high over the target on arrival (at 3 cm an object that slipped
  /// down in the grip on the way struck the bottom object of a stack and tipped it)
  double carry_clearance_m = 0.06;
  /// The transport keeps the object's base at most this far below both where it starts (lifted)
  /// and where it ends (ArmMotionOptions::carried_min_z): the demo scene's red box was carried
  /// down beside the chair, below the table's top, and back up (issue 15 session 44)
  double carry_dip_m = 0.05;
  /// When no transport pose at the grasp's own turns is reachable, the hand may end at any turn
  /// about the target's vertical, the object up to this far from upright (the alignment below
  /// turns it upright before the descent)
  double transport_tilt_tol_rad = 0.12;
  /// With carry_over_arc, the transport's searched path (RRTConnect) is replaced by an arc to
  /// the same goal pose (up, across and down, as a person carries; PlanCarryOver, the arm's
  /// posture moving toward the searched plan's end) whenever one is free. Off: over four
  /// planner seeds it placed 502 / 536 and stacked 478 / 552 against 506 / 477 without, and
  /// it leaves the roundabout transports as they were: there no arc is free, the arm folded
  /// against its limits after grasping beside the body (docs/BENCHMARKS.md, issue 15
  /// session 45).
  bool carry_over_arc = false;
  CarryOverOptions carry_over;
  double lower_speed_mps = 0.06;  ///< placing descent
  /// The descent stops to straighten the object again every this far (0: straight down once;
  /// a box held at its fingertips tilted 3 -> 20 degrees on the way down and fell after the
  /// release)
  double lower_segment_m = 0.03;
  /// Before the descent the hand turns the object upright and shifts its centre of mass over
  /// the target, reading the object's pose (it tilts and slips in the grip during transport;
  /// DASH's placing policy reads it at 20 Hz): up to `align_passes` moves of `align_s` each,
  /// until within `align_tol_m` and `align_tilt_rad`
  int align_passes = 2;
  double align_s = 0.3;
  /// After each alignment move the arm holds its target this long before the object's pose is
  /// read again (the tracker's integral takes up the load; 0: read at once)
  double align_settle_s = 0.3;
  /// While the object is in the hand, straight palm moves (lift, alignment, descent) keep the
  /// tracker's error integral, which carries the object's load (the inverse dynamics does not
  /// model it). Reset at every move, the wrist sagged by 3-13 degrees within one 3 cm descent
  /// segment and undid the alignment (docs/BENCHMARKS.md, issue 15 session 36).
  /// (Kept through the transport's planned trajectory too, stacks fell from 85.7 % to 81.4 %.)
  bool keep_load_integral = true;
  double align_tol_m = 0.005;
  double align_tilt_rad = 0.05;
  int ik_every_steps = 6;  ///< straight palm moves (lift, lower, retract) re-solve IK so often
  double release_s = 0.4;  ///< the fingers open over this long
  double settle_s = 2.0;   ///< the object must rest this long after the release
  /// Transport plans keep the object in the hand clear of other objects and the table (it moves
  /// with the hand in the collision check), so it does not knock the bottom object over on the
  /// way; off: only the arm is checked.
  bool transport_checks_object = true;
  double finger_squeeze_rad = 0.1;  ///< DASH: transport targets = grasp targets + 0.1 sign(e)
  /// When no arm pose reaches the object upright, the trunk leans forward (the pelvis stays
  /// held) by these angles in turn, as a seated person does for a far object (DASH holds its
  /// trunk and names that as a cause of its planning failures).
  std::vector<double> lean_deg = {12, 24, 34, 44};
  /// The trunk leans (by the first of `lean_deg` that does it) until the object is within this
  /// horizontal distance of the shoulder; leaning by a moves the shoulder lean_shoulder_m sin a
  /// forward.
  double comfort_reach_m = 0.6;
  double lean_shoulder_m = 0.45;
  /// When the furthest lean still reaches no arm pose (at the reach or the transport), the
  /// leaning trunk also turns about the spine (abdomen_z, degrees; + turns the front to the
  /// left), trying these turns nearest-shoulder first and skipping any that takes the shoulder
  /// further from the object (or the target) than it is.
  std::vector<double> twist_deg = {20, -20, 35, -35};
  /// A reach that starts with the palm below the table's top first lifts the hand over the
  /// table's edge through these arm angles (each: shoulder abduction, flexion, rotation, elbow,
  /// forearm, wrist flexion, deviation; PlanArmThrough), as a seated person does (the default:
  /// SeatedRaiseViaRad(), with raise_tail_m below). Empty, or no straight way through
  /// them: the reach goes for the object from the hanging arm, which swings the arm out round
  /// the table's edge (upper arm past level to the side in half the reaches: median 94 degrees
  /// from hanging, against 63 with the raise; docs/BENCHMARKS.md, issue 15, sessions 43-44).
  std::vector<std::vector<double>> raise_via_rad = SeatedRaiseViaRad();
  /// With raise_via_rad: > 0, the reach is first planned from the hanging arm; the raised hand
  /// then moves to where that reach's palm is this far (m) from its end (PathTail), keeping its
  /// distance from every object on the way, stops, and follows the rest of it (PlanArmOnto), so
  /// that it arrives as the reach from the hanging arm would. No path onto it, or 0: the reach
  /// is planned from the raised hand (the goals' arm poses still solved from the hanging arm),
  /// which misses more grasps (session 39).
  double raise_tail_m = 0.15;
};

/// The palm poses that hold the object (its base at `r_obj` and the palm at `r_palm` in the
/// hand's frame `rh`) with its base at `base_goal`: the hand turned by `upright` (which sets the
/// object upright) and then by `turns` angles about the vertical from -pi, evenly spaced.
std::vector<PalmPose> TransportPalmGoals(const Eigen::Matrix3d& rh, const Eigen::Vector3d& r_obj,
                                         const Eigen::Vector3d& r_palm,
                                         const Eigen::Matrix3d& upright,
                                         const Eigen::Vector3d& base_goal, int turns);

/// TabletopOptions::raise_via_rad as arm angles.
std::vector<Eigen::VectorXd> RaiseVias(const TabletopOptions& options);

/// How high above the object's base the palm's centre grips it (TabletopOptions' grip_*).
double GripHeightM(const TabletopGoal& goal, const TabletopOptions& options);

/// How far the object's axis lies ahead of the palm's centre along the fingers in a side grasp
/// (TabletopOptions' palm_behind_m, or for a wide object so far that its near side stays within
/// palm_behind_margin_m of the palm's centre).
double PalmBehindM(const TabletopGoal& goal, const TabletopOptions& options);

/// Whether `goal`'s object is taken from above (a sphere with sphere_top_grasp).
bool TopGrasp(const TabletopGoal& goal, const TabletopOptions& options);

/// Why a run ended.
enum class TabletopStage { kReach, kGrasp, kLift, kTransport, kPlace, kRelease, kSettle, kDone };
const char* TabletopStageName(TabletopStage s);

/// The outcome of one run.
struct TabletopResult {
  bool success = false;
  TabletopStage failed_stage = TabletopStage::kDone;  ///< kDone when nothing failed
  std::string end_reason;  ///< "success", "plan failure: ...", "grasp miss: ...", ...
  bool plan_failure = false;
  int grasp_attempts = 0;  ///< grasps begun (more than one after a miss)
  /// How the last reach went (TabletopOptions::raise_via_rad, raise_tail_m): "hanging" (from
  /// the hanging arm, as without the raise), "raised" (through the raise vias, planned from
  /// there), "raised-onto" (then onto the reach planned from the hanging arm), "raised-replanned"
  /// (no path onto it: planned from the raised hand); empty when no reach began
  std::string reach_route;
  /// How the transport went: "over" (an arc over what stands between, PlanCarryOver;
  /// TabletopOptions::carry_over_arc) or "searched" (RRTConnect); empty when no transport
  /// began
  std::string transport_route;
  /// The object's tilt from upright (degrees) when the fingers began to open over its support;
  /// -1 when the run ended before
  double release_tilt_deg = -1;
  /// The object's base above the target (m) when the fingers began to open; -1 when the run
  /// ended before
  double release_gap_m = -1;
  Eigen::Vector3d final_pos = Eigen::Vector3d::Zero();  ///< the object's centre of mass
  int sim_steps = 0;
  double wall_s = 0;
  /// The run's CPU time (its thread's): what it costs on a core of its own, however loaded the
  /// machine (wall_s grows when other processes share the cores, cpu_s barely).
  double cpu_s = 0;
};

/// The calling thread's CPU time so far (s).
double ThreadCpuSeconds();

/// Called after every physics step (recording, video); may be empty.
using StepHook = std::function<void(const mjData* d)>;

/// Makes the grasp policy of one attempt at `goal` (after a miss, the goal's planned_pos is where
/// the object now stands); policies keep per-attempt state, so each attempt gets a new one.
using GraspPolicyFactory = std::function<GraspPolicyFn(const TabletopGoal& goal)>;

/// Runs the pipeline on `world` (its data is stepped), agent `ix.arm.agent`. The body's other
/// servos keep their targets. Success is DASH's rule: the object's centre within 10 cm of the
/// target in x and y, its centre of mass at least 5 cm above the target's z, plus ours: at rest
/// (speed < 5 cm/s) `settle_s` after the release. `place_policy` (place_task.h; empty: the
/// scripted placing) corrects each descent segment.
TabletopResult RunTabletop(world::SimWorld& world, const GraspIndex& ix, const TabletopGoal& goal,
                           const GraspPolicyFactory& make_policy, const TabletopOptions& options,
                           const StepHook& hook = {}, const PlacePolicyFn& place_policy = {});

/// The pipeline's state where placing begins (the object held over the target after transport):
/// the simulation's data, the fingers' targets, the arm's tracker (its integral carries the
/// object's load), the goal and the counters. RunTabletopToPlace keeps it; RunTabletopPlace runs
/// placing from it as often as wanted (the place training's episodes).
struct PlaceStart {
  std::shared_ptr<mjData> data;
  GraspState grasp;
  std::optional<ArmTracker> tracker;
  TabletopGoal goal;
  int lean = -1, steps = 0, attempts = 0;
  bool ready() const { return data != nullptr && tracker.has_value(); }
};

/// RunTabletop up to where placing begins: the result of a stage that failed before it, or,
/// with `start` ready, a kPlace result "stopped where placing begins".
TabletopResult RunTabletopToPlace(world::SimWorld& world, const GraspIndex& ix,
                                  const TabletopGoal& goal, const GraspPolicyFactory& make_policy,
                                  const TabletopOptions& options, PlaceStart* start);

/// Placing, release and settle (RunTabletop's end, with its success rule) from `start` (made in
/// the same `world`'s model), the simulation's data reset to it first. The step and grasp counts
/// go on from the start's; the times are this call's.
TabletopResult RunTabletopPlace(world::SimWorld& world, const GraspIndex& ix,
                                const PlaceStart& start, const TabletopOptions& options,
                                const PlacePolicyFn& place_policy = {});

}  // namespace simhuman::control::manip
