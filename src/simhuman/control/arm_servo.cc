#include "simhuman/control/arm_servo.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <string>
#include <vector>

#include "simhuman/world/humanoid.h"

namespace simhuman::control {

core::StatusOr<std::array<std::array<int, 4>, 2>> ArmJointIndices() {
  const auto& names = world::HumanoidJointNames();
  std::array<std::array<int, 4>, 2> arms{};
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "right_" : "left_";
    int k = 0;
    for (const char* n : {"shoulder_x", "shoulder_y", "shoulder_z", "elbow"}) {
      auto it = std::find(names.begin(), names.end(), s + n);
      if (it == names.end()) return absl::InternalError("humanoid has no joint " + s + n);
      arms[side][k++] = static_cast<int>(it - names.begin());
    }
  }
  return arms;
}

Eigen::Vector4d ArmStepToward(const mjModel* m, const mjData* d, const world::AgentIndex& a,
                              const std::array<int, 4>& arm, int site, const Eigen::Vector3d& miss,
                              double damping) {
  std::vector<mjtNum> jacp(3 * m->nv);
  mj_jacSite(m, d, jacp.data(), nullptr, site);
  Eigen::Matrix<double, 3, 4> J;
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 4; ++k) J(r, k) = jacp[r * m->nv + a.hinge_qvel[arm[k]]];
  }
  // the smallest joint change that moves the hand by `miss`
  Eigen::Matrix3d JJt = J * J.transpose() + damping * damping * Eigen::Matrix3d::Identity();
  return J.transpose() * JJt.ldlt().solve(miss);
}

}  // namespace simhuman::control
