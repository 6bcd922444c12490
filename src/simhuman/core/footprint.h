#pragma once
/// Floor-plane measures of catalog objects: the one footprint distance of the code base.

#include <Eigen/Core>

#include "simhuman/core/geometry.h"
#include "simhuman/core/scene_catalog.h"

namespace simhuman::core {

/// Heading (radians) of `pose`'s +x axis projected on the floor; 0 when +x points straight up
/// or down.
double PoseYaw(const Pose& pose);

/// Horizontal distance (m) from the floor point `p_xy` to the object's footprint: its local
/// bounds in x and y, turned by its yaw (PoseYaw) and placed at its position; 0 inside. An
/// object without shapes is a point at its position.
double FootprintDistance(const CatalogObject& object, const Eigen::Vector2d& p_xy);

}  // namespace simhuman::core
