#include "simhuman/perceive/vision/associate.h"

#include <algorithm>
#include <limits>

namespace simhuman::perceive {

std::vector<int> HungarianAssign(const std::vector<std::vector<double>>& cost) {
  const int rows = static_cast<int>(cost.size());
  if (rows == 0) return {};
  const int cols = static_cast<int>(cost[0].size());
  std::vector<int> result(rows, -1);
  if (cols == 0) return result;
  // square the matrix with zero-cost padding; the potentials method on a 1-based n x n matrix
  const int n = std::max(rows, cols);
  auto c = [&](int i, int j) {  // 1-based
    return (i <= rows && j <= cols) ? cost[i - 1][j - 1] : 0.0;
  };
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0), v(n + 1, 0);
  std::vector<int> p(n + 1, 0), way(n + 1, 0);
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::vector<double> minv(n + 1, inf);
    std::vector<char> used(n + 1, 0);
    do {
      used[j0] = 1;
      const int i0 = p[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double cur = c(i0, j) - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= n; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const int j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  for (int j = 1; j <= n; ++j) {
    if (p[j] >= 1 && p[j] <= rows && j <= cols) result[p[j] - 1] = j - 1;
  }
  return result;
}

double AssociationCost(const ObjectEstimate& t, const ObjectEstimate& e) {
  return (t.centre - e.centre).norm() + (t.colour != e.colour ? 1.0 : 0.0) +
         (t.shape != e.shape ? 0.3 : 0.0);
}

void ObjectTracker::Reset(const std::vector<ObjectEstimate>& first) {
  objects_ = first;
  unseen_.assign(first.size(), 0);
}

void ObjectTracker::Update(const std::vector<ObjectEstimate>& frame, double gate) {
  for (int& u : unseen_) ++u;
  if (objects_.empty() || frame.empty()) return;
  std::vector<std::vector<double>> cost(objects_.size(), std::vector<double>(frame.size()));
  for (size_t i = 0; i < objects_.size(); ++i) {
    for (size_t j = 0; j < frame.size(); ++j) cost[i][j] = AssociationCost(objects_[i], frame[j]);
  }
  const std::vector<int> a = HungarianAssign(cost);
  for (size_t i = 0; i < objects_.size(); ++i) {
    if (a[i] < 0 || cost[i][a[i]] > gate) continue;
    objects_[i] = frame[a[i]];
    unseen_[i] = 0;
  }
}

}  // namespace simhuman::perceive
