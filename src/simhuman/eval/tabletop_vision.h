#pragma once
/// DASH's pipeline seeing through the head camera (issue 16): the task is planned from the first
/// frame (the objects' positions, sizes and up axes as the vision module estimates them), and the
/// controllers read the moved object's estimates at 20 Hz with a 50 ms delay (DASH Section 3.4).
/// Which simulated body is "the red box" comes from the scene's names (the command's words pick
/// it), never its position.

#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/perceive/touch.h"
#include "simhuman/perceive/vision/associate.h"
#include "simhuman/perceive/vision/silhouette.h"
#include "simhuman/perceive/vision/vision_data.h"
#include "simhuman/perceive/vision/vision_model.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {

/// How often the camera runs and how late its estimates arrive (DASH: 20 Hz, 50 ms).
struct VisionLoopOptions {
  double rate_hz = 20;
  double delay_s = 0.05;
  /// The object in the hand is read as the per-axis median of this many newest arrived frames
  /// (0.25 s at 20 Hz): the hand hides part of it and single frames err by a few cm.
  int smooth_frames = 5;
  /// The object in the hand is also kept in the hand's frame (the hand's pose at each frame's
  /// capture is known from the body's own joints): its estimate is the per-axis median of the
  /// newest `in_hand_frames` frames taken since the grip closed, carried by the hand's current
  /// pose. The hand's own moves then move the estimate exactly, and noise averages out instead
  /// of making the placing controller chase it. 0: off (the world-frame median above).
  int in_hand_frames = 20;
  /// Frames this long before the controllers first ask for the object in the hand count as
  /// held (the lift: the grip has closed and the hand rises).
  double in_hand_lead_s = 0.6;
  /// Once its place in the hand is known, the held object is the estimate of its colour within
  /// this distance of that place (none: the frame gives no estimate of it)
  double in_hand_gate_m = 0.06;
  /// The held object's estimate blends, in the hand's frame, a grasp prior (the object where
  /// task planning saw it and upright, taken into the hand's frame when the grip closed; it errs
  /// by what the grasp pushed or tipped it) with the in-hand median of the frames (its error is
  /// mostly a bias of 1-4 cm and several degrees where the hand hides the object, which the
  /// median does not average away): weight of the prior for the centre and for the up axis
  /// (chosen on 32 episodes: docs/BENCHMARKS.md, issue 16 session 22). 0: the frames alone.
  double prior_weight = 0.8;
  double prior_up_weight = 0.8;
  /// Touch (perceive/touch.h): where the hand's skin touches the held object and which way
  /// each contact pushes, read with the frames' rate and delay, corrects the held estimate's up
  /// axis and its centre across that axis (its side faces lie where the hand touches them).
  /// Boxes and cylinders; not spheres. false: the camera and the grasp prior alone (DASH's
  /// vision; its hand feels only which phalanx touches). Over the tabletop suite's 400 boxes
  /// and cylinders: place 122 / 134 and stack 101 / 138, against 121 and 97 without
  /// (docs/BENCHMARKS.md, issue 16 session 48).
  bool touch = true;
  /// With touch, also while the hand grasps: the object as the grasp sees it is the planned
  /// estimate corrected by where the hand touches it now (its centre and up axis, as for the
  /// held object), so that the grasp follows an object its palm pushes and its tilt guard sees
  /// one that tips; the grasp prior keeps the planned estimate. Touch is read with the hand's
  /// control, without the camera's delay. Over the tabletop suite's 400 boxes and cylinders
  /// (docs/BENCHMARKS.md, issue 16 session 49): see there.
  bool touch_grasp = true;
  perceive::TouchRefineOptions touch_refine;
  /// Task planning's estimates fitted to the outlines they cast in the frame
  /// (perceive/vision/silhouette.h): the grasp and the stack target are planned from them.
  bool silhouette = true;
  perceive::SilhouetteOptions silhouette_fit;
  /// Task planning looks again at the objects its frame's edge cuts (the network estimates
  /// only whole blobs): the camera turns to where each such blob meets the table's top (at
  /// most two looks), and the objects that frame sees whole join the plan's estimates unless
  /// one of their colour and shape is already estimated within `same_object_m`.
  bool second_look = true;
  double same_object_m = 0.05;
};

/// The camera and the vision model across episodes (one OpenGL context; each episode's world is
/// set with Begin()).
class TabletopVision {
 public:
  /// Errors: the model file (naming it), no EGL (naming the renderer and --perception truth).
  static core::StatusOr<std::unique_ptr<TabletopVision>> Create(const std::string& model_path,
                                                                const mjModel* first_model,
                                                                const VisionLoopOptions& o = {});

  /// Starts an episode in `world`: looks at the table, estimates the objects, and fills the
  /// geometry of `goal` (object body and shape given) from the estimates of the object of that
  /// shape and colour; for a stack, the target is the top of the estimated `support` object.
  /// Sets goal->observe to this camera's delayed estimates. NotFound when the named object is not
  /// seen (the message lists what was). `hand_body`: the hand that takes the object (its frame
  /// keeps the held object's estimates; -1: none).
  core::Status Begin(world::SimWorld& world, const core::SceneCatalog& catalog,
                     const std::string& object_id, const std::string& support_id,
                     control::manip::TabletopGoal* goal, int hand_body = -1);

  /// Call after each physics step: renders and estimates at rate_hz.
  core::Status OnStep(const mjData* d);

  /// The moved object as the controllers see it now: in the hand, the arrived (delayed)
  /// estimates, fused in the hand's frame when a hand is known; before, the task planning estimate
  /// (DASH's grasp works from the plan: the hand hides the object while it closes, and the network
  /// errs by several cm then).
  control::manip::ObjectView View(const mjData* d, bool held) const;

  int frames() const { return frames_; }
  /// The moved object's width as task planning estimated it.
  double planned_width_m() const { return planned_.width_m; }
  double vision_s() const { return vision_s_; }
  double render_s() const { return render_s_; }
  /// What task planning's silhouette fit did with the moved object's estimate (diagnostics)
  const perceive::SilhouetteFit& moved_fit() const { return moved_fit_; }
  /// The silhouette fits' time (once per episode, at task planning; not in vision_s)
  double fit_s() const { return fit_s_; }

 private:
  struct Timed {
    double t = 0;
    perceive::ObjectEstimate e;
    // the hand's pose when the frame was taken
    Eigen::Vector3d hand_pos = Eigen::Vector3d::Zero();
    Eigen::Matrix3d hand_rot = Eigen::Matrix3d::Identity();
    bool in_hand = false;  // `e` is the held object's estimate, for the in-hand median
    std::vector<perceive::TouchContact> touch;  // the held object's contacts with the hand
  };

 public:
  /// One arrived estimate of the held object in the hand's frame.
  struct InHand {
    double t = 0;
    Eigen::Vector3d centre, up;
    Eigen::Matrix3d hand_rot;  // the hand's pose when the frame was taken
    Eigen::Vector3d hand_pos;
  };

 private:
  TabletopVision() = default;
  struct PlanningLook {
    perceive::PinholeCamera cam;
    std::vector<uint8_t> rgb;
    std::vector<perceive::ObjectEstimate> est;
    std::vector<perceive::SilhouetteFit> fits;
  };
  /// One planning frame at `gaze`: captured, estimated and (with o_.silhouette) fitted.
  core::Status Look(const world::SimWorld& world, const mjData* d, const Eigen::Vector3d& gaze,
                    const perceive::SilhouetteOptions& fit, PlanningLook* look);
  /// Task planning's estimates: the table from the planning gaze, then (o_.second_look) a look
  /// at each object that frame's edge cuts, adding the objects not already seen.
  core::Status LookAtTable(const world::SimWorld& world, const mjData* d,
                           const perceive::SilhouetteOptions& fit,
                           std::vector<perceive::ObjectEstimate>* est,
                           std::vector<perceive::SilhouetteFit>* fits);
  control::manip::ObjectView ToView(const perceive::ObjectEstimate& e) const;
  /// What the grasp sees of the object before it is held (VisionLoopOptions::touch_grasp).
  control::manip::ObjectView GraspView(const mjData* d) const;

  VisionLoopOptions o_;
  std::unique_ptr<perceive::VisionModel> model_;
  std::unique_ptr<perceive::HeadCamera> camera_;
  world::SimWorld* world_ = nullptr;
  perceive::ObjectTracker tracker_;
  int moved_ = -1;  // index of the moved object in the tracker
  perceive::ObjectEstimate planned_;
  Eigen::Vector3d target_ = Eigen::Vector3d::Zero();
  std::deque<Timed> queue_;  // estimates still on their way (not yet delay_s old)
  std::deque<perceive::ObjectEstimate> arrived_;  // the newest smooth_frames that have arrived
  std::deque<InHand> in_hand_;  // the newest arrived estimates in the hand's frame
  int hand_body_ = -1;
  int object_body_ = -1;
  std::vector<bool> hand_geom_;  // per model geom: part of the hand (its body's subtree)
  std::vector<perceive::TouchContact> touch_;  // the newest arrived touch (hand frame)
  mutable bool held_ = false;      // the controllers have asked for the object in the hand
  mutable double held_since_ = 0;  // when they first did
  // the grasp prior in the hand's frame: the planned centre and up axis when the grip closed
  mutable std::optional<Eigen::Vector3d> prior_c_, prior_up_;
  mutable std::optional<Eigen::Vector3d> anchor_;  // where the hand holds the object (hand frame)
  double next_t_ = 0;
  int frames_ = 0;
  double vision_s_ = 0, render_s_ = 0, fit_s_ = 0;
  perceive::SilhouetteFit moved_fit_;
  double height_m_ = 0;
};

}  // namespace simhuman::eval
