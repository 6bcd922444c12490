#include "simhuman/control/controller.h"

#include <algorithm>
#include <cmath>

namespace simhuman::control {

void BuildHeightmap(const core::SceneCatalog& scene, const Eigen::Vector3d& pelvis, double yaw_rad,
                    int size, double cell_m, std::vector<float>* out) {
  out->assign(static_cast<size_t>(size) * size, 0.0f);
  double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  // only objects that can reach into the map's square
  const double half_diag = 0.7072 * size * cell_m;
  std::vector<const core::CatalogObject*> near;
  for (const auto& o : scene.objects) {
    if (!o.collides || o.shapes.empty()) continue;
    auto [lo, hi] = o.LocalBounds();
    double radius = std::max(lo.head<2>().norm(), hi.head<2>().norm()) +
                    std::max(std::abs(lo.x()), std::abs(hi.x()));
    if ((o.pose.pos.head<2>() - pelvis.head<2>()).norm() < half_diag + radius) near.push_back(&o);
  }
  for (int i = 0; i < size; ++i) {
    for (int j = 0; j < size; ++j) {
      double lx = (i - (size - 1) / 2.0) * cell_m, ly = (j - (size - 1) / 2.0) * cell_m;
      Eigen::Vector3d probe(pelvis.x() + c * lx - s * ly, pelvis.y() + s * lx + c * ly, 3.0);
      float h = 0;
      for (const core::CatalogObject* o : near) {
        for (const auto& shape : o->shapes) {
          // a vertical probe hits the shape if the nearest point of a low point is under it
          Eigen::Vector3d low(probe.x(), probe.y(), -1.0);
          Eigen::Vector3d np = core::NearestPointOnShape(shape, o->pose, probe);
          Eigen::Vector3d np_low = core::NearestPointOnShape(shape, o->pose, low);
          if ((np.head<2>() - probe.head<2>()).norm() < 1e-6 &&
              (np_low.head<2>() - probe.head<2>()).norm() < 1e-6) {
            h = std::max(h, static_cast<float>(np.z()));
          }
        }
      }
      (*out)[static_cast<size_t>(i) * size + j] = h;
    }
  }
}

}  // namespace simhuman::control
