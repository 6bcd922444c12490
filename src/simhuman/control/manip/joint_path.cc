#include "simhuman/control/manip/joint_path.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <utility>

#include "simhuman/core/check.h"

namespace simhuman::control::manip {

double JointPath::Length() const {
  double length = 0;
  for (size_t i = 1; i < waypoints.size(); ++i) length += (waypoints[i] - waypoints[i - 1]).norm();
  return length;
}

std::vector<double> CumulativeLengths(const JointPath& path) {
  std::vector<double> cumulative(path.waypoints.size(), 0.0);
  for (size_t i = 1; i < path.waypoints.size(); ++i) {
    cumulative[i] = cumulative[i - 1] + (path.waypoints[i] - path.waypoints[i - 1]).norm();
  }
  return cumulative;
}

int SegmentAt(const std::vector<double>& cumulative, double s) {
  const int segments = static_cast<int>(cumulative.size()) - 1;
  if (segments < 1) return 0;
  // first segment whose end reaches s; skips zero-length segments before it
  const auto it = std::lower_bound(cumulative.begin() + 1, cumulative.end(), s);
  const int i = static_cast<int>(it - cumulative.begin()) - 1;
  return std::clamp(i, 0, segments - 1);
}

Eigen::VectorXd PointAt(const JointPath& path, double s, const std::vector<double>* cumulative) {
  SH_CHECK(!path.waypoints.empty(), "PointAt on an empty path");
  if (path.waypoints.size() == 1) return path.waypoints[0];
  std::vector<double> own;
  if (cumulative == nullptr) {
    own = CumulativeLengths(path);
    cumulative = &own;
  }
  SH_CHECK(cumulative->size() == path.waypoints.size(), "cumulative lengths of another path");
  const double length = cumulative->back();
  s = std::clamp(s, 0.0, length);
  const int i = SegmentAt(*cumulative, s);
  const double seg = (*cumulative)[i + 1] - (*cumulative)[i];
  if (seg <= 0) return path.waypoints[i + 1];
  const double u = std::clamp((s - (*cumulative)[i]) / seg, 0.0, 1.0);
  return path.waypoints[i] + u * (path.waypoints[i + 1] - path.waypoints[i]);
}

bool SegmentValid(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const ValidityFn& valid,
                  double resolution_rad) {
  SH_CHECK(resolution_rad > 0, "segment check resolution must be > 0");
  SH_CHECK(a.size() == b.size(), "segment endpoints of different sizes");
  if (!a.allFinite() || !b.allFinite()) return false;
  if (!valid(b)) return false;
  const double steps = std::ceil((b - a).cwiseAbs().maxCoeff() / resolution_rad);
  SH_CHECK(steps < 1e8, "segment check would need more than 1e8 states");
  const int n = static_cast<int>(steps);
  if (n <= 1) return true;
  // interior states k / n, k = 1 .. n-1, each once, midpoints first
  const Eigen::VectorXd delta = b - a;
  std::deque<std::pair<int, int>> intervals{{0, n}};
  while (!intervals.empty()) {
    const auto [lo, hi] = intervals.front();
    intervals.pop_front();
    if (hi - lo < 2) continue;
    const int mid = (lo + hi) / 2;
    if (!valid(a + (static_cast<double>(mid) / n) * delta)) return false;
    intervals.emplace_back(lo, mid);
    intervals.emplace_back(mid, hi);
  }
  return true;
}

bool PathValid(const JointPath& path, const ValidityFn& valid, double resolution_rad) {
  if (path.waypoints.empty() || !path.waypoints[0].allFinite() || !valid(path.waypoints[0])) {
    return false;
  }
  for (size_t i = 1; i < path.waypoints.size(); ++i) {
    if (!SegmentValid(path.waypoints[i - 1], path.waypoints[i], valid, resolution_rad)) {
      return false;
    }
  }
  return true;
}

absl::Status ShortcutOptions::Validate() const {
  if (iterations < 0) {
    return absl::InvalidArgumentError("shortcut: iterations = " + std::to_string(iterations) +
                                      " must be >= 0");
  }
  if (!(resolution_rad > 0 && resolution_rad <= 1.0)) {
    return absl::InvalidArgumentError(
        "shortcut: resolution_rad = " + std::to_string(resolution_rad) + " must be in (0, 1] rad");
  }
  if (!(partial_fraction >= 0 && partial_fraction <= 1)) {
    return absl::InvalidArgumentError(
        "shortcut: partial_fraction = " + std::to_string(partial_fraction) + " must be in [0, 1]");
  }
  if (!(min_gain_rad >= 0 && std::isfinite(min_gain_rad))) {
    return absl::InvalidArgumentError("shortcut: min_gain_rad = " + std::to_string(min_gain_rad) +
                                      " must be finite and >= 0");
  }
  return absl::OkStatus();
}

absl::Status CheckPath(const JointPath& path, int num_dofs) {
  if (path.waypoints.empty()) return absl::InvalidArgumentError("joint path: no waypoints");
  const int n = num_dofs >= 0 ? num_dofs : path.num_dofs();
  for (size_t i = 0; i < path.waypoints.size(); ++i) {
    const Eigen::VectorXd& w = path.waypoints[i];
    if (w.size() != n) {
      return absl::InvalidArgumentError("joint path: waypoint " + std::to_string(i) + " has " +
                                        std::to_string(w.size()) + " joints, expected " +
                                        std::to_string(n));
    }
    for (int j = 0; j < n; ++j) {
      if (!std::isfinite(w[j])) {
        return absl::InvalidArgumentError("joint path: waypoint " + std::to_string(i) + " joint " +
                                          std::to_string(j) + " is not finite");
      }
    }
  }
  return absl::OkStatus();
}

namespace {

// drops consecutive repeats (closer than 1e-12 rad), keeping the last endpoint exactly
void DropRepeats(std::vector<Eigen::VectorXd>* wp) {
  constexpr double kSame = 1e-12;
  std::vector<Eigen::VectorXd> out;
  out.reserve(wp->size());
  for (size_t i = 0; i < wp->size(); ++i) {
    if (!out.empty() && ((*wp)[i] - out.back()).norm() <= kSame) {
      if (i + 1 == wp->size() && out.size() > 1) out.back() = (*wp)[i];
      continue;
    }
    out.push_back((*wp)[i]);
  }
  *wp = std::move(out);
}

// One shortcut attempt between arc lengths s1 < s2 of `wp`: the straight segment (joint < 0)
// or, for a partial shortcut, the same sub-path with only `joint` interpolated linearly in arc
// length. Replaces the part of `wp` in between and returns true when valid and shorter.
bool TryShortcut(std::vector<Eigen::VectorXd>* wp, double s1, double s2, int joint,
                 const ValidityFn& valid, const ShortcutOptions& options) {
  JointPath work;
  work.waypoints = *wp;  // cheap for the short paths planners return
  const std::vector<double> cum = CumulativeLengths(work);
  const int i1 = SegmentAt(cum, s1);
  const int i2 = SegmentAt(cum, s2);
  if (i1 == i2) return false;  // both on one straight segment: nothing to gain
  const Eigen::VectorXd p1 = PointAt(work, s1, &cum);
  const Eigen::VectorXd p2 = PointAt(work, s2, &cum);
  // the replacement p1, ..., p2
  std::vector<Eigen::VectorXd> middle{p1};
  if (joint >= 0) {
    for (int k = i1 + 1; k <= i2; ++k) {
      Eigen::VectorXd q = (*wp)[k];
      q[joint] = p1[joint] + (cum[k] - s1) / (s2 - s1) * (p2[joint] - p1[joint]);
      middle.push_back(std::move(q));
    }
  }
  middle.push_back(p2);
  double length = 0;
  for (size_t k = 1; k < middle.size(); ++k) length += (middle[k] - middle[k - 1]).norm();
  if ((s2 - s1) - length <= options.min_gain_rad) return false;
  for (size_t k = 1; k < middle.size(); ++k) {
    if (!SegmentValid(middle[k - 1], middle[k], valid, options.resolution_rad)) return false;
  }
  // waypoints 0..i1, the replacement, i2+1..end
  std::vector<Eigen::VectorXd> next(wp->begin(), wp->begin() + i1 + 1);
  next.insert(next.end(), middle.begin(), middle.end());
  next.insert(next.end(), wp->begin() + i2 + 1, wp->end());
  DropRepeats(&next);
  *wp = std::move(next);
  return true;
}

}  // namespace

core::StatusOr<JointPath> ShortcutPath(const JointPath& path, const ValidityFn& valid,
                                       const ShortcutOptions& options, core::Rng& rng) {
  SH_RETURN_IF_ERROR(options.Validate());
  SH_RETURN_IF_ERROR(CheckPath(path));
  std::vector<Eigen::VectorXd> wp = path.waypoints;
  DropRepeats(&wp);
  const int n = path.num_dofs();
  for (int it = 0; it < options.iterations && wp.size() > 2; ++it) {
    double length = 0;
    for (size_t k = 1; k < wp.size(); ++k) length += (wp[k] - wp[k - 1]).norm();
    if (length <= 0) break;
    double s1 = rng.Uniform(0.0, length);
    double s2 = rng.Uniform(0.0, length);
    if (s1 > s2) std::swap(s1, s2);
    const int joint = rng.Uniform() < options.partial_fraction ? rng.UniformInt(0, n - 1) : -1;
    TryShortcut(&wp, s1, s2, joint, valid, options);
  }
  // deterministic pass: drop interior waypoints whose neighbours see each other
  for (size_t i = 1; i + 1 < wp.size();) {
    if (SegmentValid(wp[i - 1], wp[i + 1], valid, options.resolution_rad)) {
      wp.erase(wp.begin() + static_cast<std::ptrdiff_t>(i));
    } else {
      ++i;
    }
  }
  JointPath out;
  out.waypoints = std::move(wp);
  return out;
}

}  // namespace simhuman::control::manip
