#pragma once
/// A training-free grasp for the pipeline's grasp stage, the baseline a learned policy is
/// measured against. The hand arrives open with the thumb pre-shaped into a C (grasp_task.h
/// SetOpenHand); the palm closes in along its normal by inverse kinematics from the current
/// targets until it touches; then each finger wraps from its base (the MCP until a phalanx
/// touches, the PIP once the proximal phalanx touches, the DIP once the middle one does, so
/// fingertips never curl in under the object and push it out), the thumb closes a quarter
/// second later, and touching segments keep a slow squeeze while the palm keeps pressing. The
/// palm closes in at the height where the reach left it (the grip height, or higher up on a far
/// object). With TabletopOptions::sphere_top_grasp a sphere is taken from above: the palm comes
/// down on its top and the thumb closes with the fingers.

#include <cmath>

#include "simhuman/control/manip/tabletop_pipeline.h"

namespace simhuman::control::manip {

/// Settings of the scripted grasp (steps are policy steps, 40 Hz).
struct ScriptedGraspOptions {
  int approach_steps = 40;          ///< the palm closes in this long at most before the hand closes
  double press_m = 0.006;           ///< the palm's goal lies this far inside the object's side
  bool press_while_closing = true;  ///< the palm keeps pressing on the object as the hand closes
  int finger_delay_steps = 0;       ///< the four fingers start flexing this many steps after touch
  int thumb_delay_steps = 10;       ///< the thumb starts this many steps after touch
  float close_rate = 0.6;           ///< finger action while closing (x kFingerStepRad per step)
  float hold_rate = 0.05;           ///< a touching segment's action: a slow squeeze
  /// IkOptions::rot_weight_m of the approach: the hand may turn a little to close the gap when
  /// the arm is near its limits
  double ik_rot_weight_m = 0.03;
  /// The approach's rotation target is the hand's rotation when the grasp began; false: its
  /// current rotation (it then drifts with every push on the hand)
  bool hold_rotation = true;
  /// Once the palm touches, its goal lies `press_m` past where it is, not `press_m` inside the
  /// side the object's centre and half width give: a palm that meets a box's side at an angle,
  /// or at its edge, chased that side and pushed the object over (0-200 and 200-400 of the
  /// tabletop suite, boxes and cylinders: 227 of 272 placed against 222)
  bool touch_ends_gap = true;
  /// Until the palm first touches, its goal also moves along the fingers so that the object's
  /// axis lies PalmBehindM ahead of the palm's centre, as the reach planned: the reach arrives
  /// moving and its lag left the palm 1-2 cm further back, where the object met the fingers
  /// before the palm (issue 15 session 37: no palm touch in 5 of the 7 single-attempt place
  /// misses). false: the palm closes in along its normal only.
  bool hold_behind = true;
  double behind_tol_m = 0.01;  ///< hold_behind corrects only what lies beyond this
  /// While the palm has stalled short of the object (its gap changed by less than `stall_m` in
  /// a step) with no part of the hand touching it (a finger or the thumb that blocks the palm
  /// would push the object over), the gap still to close accumulates (x this per step, at
  /// most `push_max_m`) into an extra push along the palm's normal, dropped at the touch: the
  /// arm's servos sag, and the palm stopped 6-10 mm short of the object with its targets
  /// already at the goal (issue 15 session 37). 0: no push.
  double push_gain = 0.15;
  double push_max_m = 0.03;
  double stall_m = 0.0005;
  /// Once the palm has touched, while it is off the object again in the first `repress_steps`
  /// of the hand's closing, the gap accumulates (x this per step, at most `repress_max_m`) into
  /// an extra press along the palm's normal, kept to the end of the grasp: the closing fingers
  /// pushed the palm 1-1.4 cm off the demo scene's red box and its first grasp missed with
  /// every reach (issue 15 sessions 43-44). A press that grew for the whole grasp held a 4 kg
  /// box tilted by 5 degrees when it was set down. 0: off.
  double repress_gain = 0.15;
  double repress_max_m = 0.005;
  int repress_steps = 10;
  /// Once the object has tilted this much more than when the grasp began (the hand is pushing
  /// it over before the fingers hold it), the palm's goal stays `tilt_backoff_m` behind where the
  /// palm was when the tilt was first seen, instead of pressing on, until the object stands
  /// again. A palm or a finger pressing on one side tipped tall boxes and cylinders before the
  /// hand closed (issue 15 session 40). The guard watches until `tilt_guard_steps` after the
  /// hand starts closing: a later tilt comes from the fingers' own wrap, and backing off then
  /// loosened the grip (a 4 kg box was set down 6 degrees off upright). 0: no guard.
  double tilt_guard_rad = 4 * M_PI / 180;
  double tilt_backoff_m = 0.003;
  int tilt_guard_steps = 20;
  /// While the thumb touches the object before the palm does (the thumb's base, shaped into a
  /// C, meets the object's near edge and pushes it over as the palm closes in), the object's
  /// axis is taken this much further along the fingers each step (at most
  /// `thumb_clear_max_m`): the hand slides away from the thumb's side. 0: off.
  double thumb_clear_step_m = 0.002;
  double thumb_clear_max_m = 0.02;
};

/// The scripted grasp of `goal`'s object by arm `ix` in the simulation `m`/`d` (read at each
/// call; the pipeline steps `d`), at the grip height of the pipeline's `pipeline` settings.
/// The function keeps its own scratch data and step count; one per episode.
GraspPolicyFn MakeScriptedGrasp(const mjModel* m, const mjData* d, const GraspIndex& ix,
                                const TabletopGoal& goal, const TabletopOptions& pipeline,
                                const ScriptedGraspOptions& options = {});

}  // namespace simhuman::control::manip
