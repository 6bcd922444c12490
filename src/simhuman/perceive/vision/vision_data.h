#pragma once
/// What the camera should see, for training and scoring the vision module: the tabletop objects'
/// true attributes, which pixels show them (MuJoCo's segmentation render), and the head camera
/// that renders both from a seated human's eyes.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/perceive/vision/detect.h"
#include "simhuman/perceive/vision/head_camera.h"
#include "simhuman/perceive/vision/vision_model.h"
#include "simhuman/render/offscreen.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::perceive {

/// One tabletop object's true state (boxes, cylinders and spheres of the vision colours).
struct ObjectTruth {
  std::string id;
  int body = -1;
  int shape = 0, colour = 0;  ///< indices into VisionShapes(), VisionColours()
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< world: its solids' bounding-box centre
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();     ///< its body's z axis (a sphere: world z)
  double height_m = 0;
  double width_m = 0;    ///< a box's side, a cylinder's or sphere's diameter
  double yaw_rad = 0;    ///< world yaw of its body's x axis
  int pixels = 0;        ///< how many pixels of the last labelled frame show it
  bool at_edge = false;  ///< some of them on the frame's edge (partly out of view)
};

/// The objects of `catalog` the vision module knows, at their poses in `d`.
std::vector<ObjectTruth> TableObjectsTruth(const world::SimWorld& world,
                                           const core::SceneCatalog& catalog, const mjData* d);

/// The table region DASH's human looks at while planning (the centre of the object region of
/// world/tabletop.h, on the table top).
Eigen::Vector3d PlanningGaze();

/// An RGB camera at agent `agent`'s eyes (head_camera.h) with its own offscreen renderer (no
/// multisampling: exact edges, and a third of the cost). A renderer draws the model it was made
/// from: make one per world.
class HeadCamera {
 public:
  /// Errors: Unavailable when no EGL display works (the message names the renderer and the
  /// `--perception truth` fallback), InvalidArgument for bad sizes.
  static core::StatusOr<std::unique_ptr<HeadCamera>> Create(const mjModel* m, int width, int height,
                                                            double fovy_deg);
  /// Switches to another world's model (same image size), keeping the OpenGL context.
  core::Status SetModel(const mjModel* m) { return renderer_->SetModel(m); }
  /// The camera looking from the agent's eyes at `gaze` in `d` (after kinematics).
  PinholeCamera Aim(const world::SimWorld& world, const mjData* d, int agent,
                    const Eigen::Vector3d& gaze) const;
  core::Status Capture(const mjData* d, const PinholeCamera& cam, std::vector<uint8_t>* rgb);
  /// The body each pixel shows (-1: none).
  core::Status CaptureBodyIds(const mjData* d, const PinholeCamera& cam, std::vector<int>* ids);
  /// The renderer's own time per frame, mean over Capture calls (seconds).
  double mean_frame_s() const { return frames_ ? frame_s_ / frames_ : 0; }

 private:
  std::unique_ptr<render::OffscreenRenderer> renderer_;
  int width_ = 0, height_ = 0;
  double fovy_deg_ = 45;
  double frame_s_ = 0;
  int frames_ = 0;
};

/// Counts each truth object's pixels in `ids` (a width x height frame) into ObjectTruth::pixels,
/// and whether any lies on the frame's edge.
void CountPixels(const std::vector<int>& ids, int width, int height,
                 std::vector<ObjectTruth>* truth);

/// Adds a frame's pixels to a colour table: object pixels as their colour, all others as
/// background.
void AddColourPixels(const std::vector<uint8_t>& rgb, const std::vector<int>& ids,
                     const std::vector<ObjectTruth>& truth, ColourTable* table);

/// The network's training samples of one frame: each blob labelled by the object most of its
/// pixels show ("not an object" when none does).
std::vector<BlobSample> LabelledSamples(const std::vector<uint8_t>& rgb,
                                        const std::vector<int>& ids, const PinholeCamera& cam,
                                        const std::vector<ObjectTruth>& truth,
                                        const std::vector<Blob>& blobs);

}  // namespace simhuman::perceive
