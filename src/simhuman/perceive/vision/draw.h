#pragma once
/// Drawing what the vision module saw onto its frame, for the docs and for looking: each
/// estimate as a cross at its centre and a line along its up axis over its height, in its
/// colour with a white outline; true centres (when given) as small black squares.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "simhuman/perceive/vision/head_camera.h"
#include "simhuman/perceive/vision/vision_model.h"

namespace simhuman::perceive {

void DrawEstimates(const PinholeCamera& cam, const std::vector<ObjectEstimate>& estimates,
                   const std::vector<Eigen::Vector3d>& true_centres, std::vector<uint8_t>* rgb);

/// The outline each upright estimate casts (silhouette.h: the solid its shape, size, yaw and
/// place give, ray by ray through pixel centres), drawn in white where a pixel the solid covers
/// borders one it does not.
void DrawOutlines(const PinholeCamera& cam, const std::vector<ObjectEstimate>& estimates,
                  std::vector<uint8_t>* rgb);

}  // namespace simhuman::perceive
