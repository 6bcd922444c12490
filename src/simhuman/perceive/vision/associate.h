#pragma once
/// Keeping track of the table's objects across frames, as DASH does: each new frame's estimates
/// are assigned to the tracked objects by the Hungarian method on a cost of predicted attributes
/// (position, colour, shape), so an object keeps its identity while the hand moves it.

#include <vector>

#include "simhuman/perceive/vision/vision_model.h"

namespace simhuman::perceive {

/// The minimum-cost assignment of rows to columns of `cost` (rows x cols, any shape): result[r]
/// is the column of row r, or -1 when rows outnumber columns and r is left out. O(n^3).
std::vector<int> HungarianAssign(const std::vector<std::vector<double>>& cost);

/// Cost of calling estimate `e` the tracked object `t`: metres apart plus fixed penalties for a
/// different colour or shape.
double AssociationCost(const ObjectEstimate& tracked, const ObjectEstimate& e);

/// Tracked objects, updated from each frame's estimates.
class ObjectTracker {
 public:
  /// Starts from the estimates of the first frame (task planning).
  void Reset(const std::vector<ObjectEstimate>& first);
  /// Assigns `frame` to the tracked objects; an assignment costing more than `gate` is refused
  /// (that estimate is ignored, the object keeps its last estimate and counts as unseen).
  void Update(const std::vector<ObjectEstimate>& frame, double gate = 0.5);
  const std::vector<ObjectEstimate>& objects() const { return objects_; }
  /// Frames since each tracked object was last seen (0: in the last frame).
  const std::vector<int>& unseen_frames() const { return unseen_; }

 private:
  std::vector<ObjectEstimate> objects_;
  std::vector<int> unseen_;
};

}  // namespace simhuman::perceive
