#pragma once
/// The vision network: for each coloured blob of an egocentric frame (detect.h), a small CNN on
/// a 32x32 crop (RGB and the blob's mask) and the blob's viewing rays predicts the object's
/// shape (or "not an object"), its centre (world, through the camera pose), its height and its
/// up axis. DASH runs Mask R-CNN and a ResNet-18 per stage at 480x480 on a GPU; this runs on one
/// CPU core in a few milliseconds per frame (docs/BENCHMARKS.md, issue 16).
///
/// The header is Torch-free; the network lives behind a pointer.

#include <Eigen/Core>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/perceive/vision/detect.h"
#include "simhuman/perceive/vision/head_camera.h"

namespace simhuman::perceive {

/// One object as the camera sees it.
struct ObjectEstimate {
  int shape = 0;                                     ///< index into VisionShapes()
  int colour = 0;                                    ///< index into VisionColours()
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< world, metres
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();     ///< world, unit
  double height_m = 0;
  double width_m = 0;     ///< a box's side, a cylinder's or sphere's diameter
  double yaw_rad = 0;     ///< a box's turn about the vertical, in (-pi/4, pi/4] (its faces repeat)
  double confidence = 0;  ///< the network's probability of its shape class
  int pixels = 0;         ///< the blob's size in the frame
  double u = 0, v = 0;    ///< the blob's centroid in the frame
};

/// What one blob gives the network, and (for training) what it should answer.
inline constexpr int kVisionCrop = 32;
inline constexpr int kVisionFeatures = 15;
struct BlobSample {
  std::vector<float> crop;  ///< 4 x kVisionCrop x kVisionCrop: R, G, B in [-0.5, 0.5], mask
  std::array<float, kVisionFeatures> features{};
  Eigen::Vector3d ray = Eigen::Vector3d::UnitX();  ///< centroid ray, level frame
  // targets: shape index, or VisionShapes().size() for "not an object"; level frame, from the eye
  int shape = 0;
  Eigen::Vector3d rel = Eigen::Vector3d::Zero();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double height_m = 0, width_m = 0;
  double yaw_rad = 0;  ///< boxes: world yaw of a face normal (any of the four)
};

/// The network's input for `blob` of frame `rgb` seen by `cam`.
BlobSample MakeBlobSample(const std::vector<uint8_t>& rgb, const PinholeCamera& cam,
                          const Blob& blob);

/// Losses of one training pass (means over samples; position in cm).
struct VisionLosses {
  double total = 0, shape = 0, position_cm = 0, height_cm = 0, width_cm = 0, up = 0;
  double yaw_deg = 0;  ///< boxes: mean error of the face yaw (degrees, modulo 90)
};

class VisionModel {
 public:
  /// A freshly initialised network (seeded) with an empty colour table.
  static std::unique_ptr<VisionModel> Create(uint64_t seed);
  /// Reads a model file (`simhuman train --task vision`). Errors name the file: NotFound, or
  /// DataLoss for a file that is not a simhuman vision model, is corrupt, or holds tensors of the
  /// wrong shape.
  static core::StatusOr<std::unique_ptr<VisionModel>> Load(const std::string& path);
  ~VisionModel();

  /// Threads LibTorch uses in this process (inference is measured on one: DASH's budget is per
  /// core).
  static void SetThreads(int n);

  /// Writes the network and the colour table (a LibTorch archive).
  core::Status Save(const std::string& path) const;

  ColourTable& colours() { return colours_; }
  const ColourTable& colours() const { return colours_; }

  /// The objects in one frame: blobs of >= min_pixels, then the network on all of them in one
  /// batch; blobs touching the frame's edge (an object partly out of view), blobs it calls "not
  /// an object", and smaller blobs whose estimate lies within merge_m of a larger one's of the
  /// same colour are dropped. Runs on the calling thread.
  std::vector<ObjectEstimate> Estimate(const std::vector<uint8_t>& rgb,
                                       const PinholeCamera& cam) const;

  /// One epoch of Adam over `samples` in shuffled minibatches; returns the mean losses.
  VisionLosses TrainEpoch(const std::vector<BlobSample>& samples, int batch, double lr,
                          uint64_t seed);
  /// Losses on `samples` without training.
  VisionLosses Evaluate(const std::vector<BlobSample>& samples) const;

  int min_pixels = 12;
  /// Estimates of one colour closer than this are one object split by an occluder (tabletop
  /// objects are at least 9.75 cm across, so two of them cannot be this close).
  double merge_m = 0.06;
  /// The camera it was trained for (frames should come from the same size and field of view).
  int width = 160, height = 120;
  double fovy_deg = 60;

 private:
  VisionModel();
  struct Net;
  std::unique_ptr<Net> net_;
  ColourTable colours_;
};

}  // namespace simhuman::perceive
