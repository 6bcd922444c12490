#pragma once
/// Fitting the network's estimates of objects resting upright on a table to the pixels they
/// cover. The vision network (vision_model.h) reads a 32x32 crop and places an object to about a
/// centimetre; a grasp planned from a position 0.4-1.8 cm off misses (docs/BENCHMARKS.md,
/// issue 16, session 48). With the camera's pose known, the object's outline is fixed by its
/// shape, size, yaw and place: the fit moves the estimate (horizontal position, width, height,
/// a box's yaw) until the outline it casts, ray by ray, covers the object's blob, its base kept
/// on the table's plane. Pixels of other objects may hide it
/// and count neither way. Torch-free.

#include <cstdint>
#include <limits>
#include <vector>

#include "simhuman/perceive/vision/detect.h"
#include "simhuman/perceive/vision/head_camera.h"
#include "simhuman/perceive/vision/vision_model.h"

namespace simhuman::perceive {

struct SilhouetteOptions {
  /// The height (world z) of the surface the objects stand on, when known (the table a seated
  /// human works at is part of its fixed surroundings, as a place task's location is): it sets
  /// the scale a single view leaves open (an object twice as far and twice as large casts the
  /// same outline). NaN: the median of the estimates' base heights (each errs by about 0.3 cm,
  /// which moves a fit's distance along the view by as much).
  double table_z = std::numeric_limits<double>::quiet_NaN();
  /// Estimates whose up axis is more than this from vertical are not resting upright: not fitted.
  double max_tilt_deg = 12;
  /// Rays per pixel along each image axis (coverage in steps of 1/supersample^2).
  int supersample = 2;
  /// A fit that moves the centre farther than this (horizontally), or changes width or height by
  /// more than max_resize_m, is not believed (a merged or half-hidden blob).
  double max_shift_m = 0.03;
  double max_resize_m = 0.03;
  /// Nor is one whose outline still disagrees with more than this share of the blob's pixels.
  double max_mismatch = 0.2;
  /// When more than this share of the fitted outline falls on other objects (which may hide it),
  /// its base may be hidden and its distance along the view is not seen: such an object is
  /// fitted again across the view and in width only.
  double max_hidden = 0.05;
  /// A pull towards the network's estimate, in mismatched pixels per square centimetre of
  /// change in position, width or height: where the outline leaves a direction open (the base
  /// of an object hidden behind another) the fit stays near the network's estimate instead of
  /// wandering along it. An edge moved by a millimetre changes tens of pixels' coverage, so
  /// it barely moves a fit of a fully seen object.
  double prior_per_cm2 = 2;
  /// The search's first and last steps (metres for position and size, degrees for yaw).
  double first_step_m = 0.004, last_step_m = 0.0005;
  double first_yaw_step_deg = 4, last_yaw_step_deg = 0.5;
};

/// What one fit did (for tests and the benchmark).
struct SilhouetteFit {
  bool fitted = false;         ///< tried (resting upright, its blob found)
  bool accepted = false;       ///< the fitted estimate replaced the network's
  bool sideways_only = false;  ///< partly hidden: fitted across the view and in width only
  double hidden = 0;           ///< share of the first fit's outline on other objects' pixels
  double before = 0;           ///< mismatched pixels (coverage units) of the network's estimate
  double after = 0;            ///< and of the fit
  int blob_pixels = 0;
};

/// Fits each estimate of `est` (VisionModel::Estimate on `rgb` seen by `cam`, whose colours
/// `table` classifies) to its blob as above; returns one SilhouetteFit per estimate. Estimates
/// whose fit is not believed are left as they were.
std::vector<SilhouetteFit> FitRestingSilhouettes(const std::vector<uint8_t>& rgb,
                                                 const PinholeCamera& cam, const ColourTable& table,
                                                 const SilhouetteOptions& options,
                                                 std::vector<ObjectEstimate>* est);

/// Whether the ray from `eye` along `dir` hits the solid of `e` stood upright (its up axis taken
/// as +z, a box turned by its yaw) in front of the eye. Exposed for tests.
bool RayHitsUpright(const ObjectEstimate& e, const Eigen::Vector3d& eye,
                    const Eigen::Vector3d& dir);

}  // namespace simhuman::perceive
