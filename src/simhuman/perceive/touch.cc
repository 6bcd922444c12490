#include "simhuman/perceive/touch.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace simhuman::perceive {

std::vector<bool> SubtreeGeoms(const mjModel* m, int body) {
  std::vector<bool> in(m->ngeom, false);
  for (int g = 0; g < m->ngeom && body > 0; ++g) {
    for (int b = m->geom_bodyid[g]; b > 0; b = m->body_parentid[b]) {
      if (b == body) in[g] = true;
    }
  }
  return in;
}

std::vector<TouchContact> HandTouch(const mjModel* m, const mjData* d,
                                    const std::vector<bool>& hand_geoms, int hand_body,
                                    int object_body) {
  std::vector<TouchContact> out;
  if (hand_body < 0 || object_body < 0) return out;
  const Eigen::Vector3d hand_pos(d->xpos + 3 * hand_body);
  const Eigen::Matrix3d hand_rot =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * hand_body);
  for (int c = 0; c < d->ncon; ++c) {
    const mjContact& con = d->contact[c];
    const bool obj1 = m->geom_bodyid[con.geom1] == object_body;
    const bool obj2 = m->geom_bodyid[con.geom2] == object_body;
    if (!((obj1 && hand_geoms[con.geom2]) || (obj2 && hand_geoms[con.geom1]))) continue;
    // MuJoCo's contact normal points from geom1 to geom2
    Eigen::Vector3d normal(con.frame[0], con.frame[1], con.frame[2]);
    if (obj2) normal = -normal;
    const Eigen::Vector3d point(con.pos[0], con.pos[1], con.pos[2]);
    out.push_back({hand_rot.transpose() * (point - hand_pos), hand_rot.transpose() * normal});
  }
  return out;
}

bool RefineHeldByTouch(const std::vector<TouchContact>& contacts, double radius,
                       const TouchRefineOptions& o, Eigen::Vector3d* centre, Eigen::Vector3d* up) {
  const Eigen::Vector3d u0 = up->normalized();
  std::vector<const TouchContact*> side;
  for (const TouchContact& c : contacts) {
    if (std::abs(c.normal.dot(u0)) < o.side_cos) side.push_back(&c);
  }
  if (side.empty()) return false;
  // the up axis: the direction most square to every side normal, held near the estimate
  Eigen::Matrix3d m = o.prior_weight * (Eigen::Matrix3d::Identity() - u0 * u0.transpose());
  for (const TouchContact* c : side) m += c->normal * c->normal.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
  Eigen::Vector3d u = eig.eigenvectors().col(0).normalized();  // smallest eigenvalue first
  if (u.dot(u0) < 0) u = -u;
  if (std::acos(std::min(1.0, u.dot(u0))) > o.max_turn_rad) return false;
  // the centre across the axis: each touched side face lies `radius` from it along its normal
  const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - u * u.transpose();
  Eigen::Matrix3d a = o.prior_weight * across + u * u.transpose();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const TouchContact* c : side) {
    Eigen::Vector3d k = across * c->normal;
    if (k.norm() < 1e-6) continue;
    k.normalize();
    a += k * k.transpose();
    b += k * k.dot(c->point - radius * k - *centre);
  }
  const Eigen::Vector3d shift = a.ldlt().solve(b);
  if (shift.norm() > o.max_shift_m) return false;
  *centre += shift;
  *up = u;
  return true;
}

}  // namespace simhuman::perceive
