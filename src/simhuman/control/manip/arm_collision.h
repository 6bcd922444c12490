#pragma once
/// The arm planner's collision check, made cheap: a validity check only counts contacts of the
/// arm (and of an object carried in the hand), yet mj_collision finds every contact of the
/// model, most of them objects resting on the table or the seated body on its chair. ArmCollider
/// lists once the geom pairs that can give a counted contact (MuJoCo's own filters: contype and
/// conaffinity, excluded body pairs, a body and its parent, bodies welded together) and runs
/// MuJoCo's narrow-phase functions (mjCOLLISIONFUNC, after its bounding-sphere test, and for a
/// box after testing the other geom's bounding sphere against the box) on those alone, so it
/// finds the same contacts of those pairs as mj_collision, for a fraction of the time
/// (ArmCollisionTest compares both on many arm poses).

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <vector>

#include "simhuman/control/manip/arm_ik.h"

namespace simhuman::control::manip {

class ArmCollider {
 public:
  /// Pairs of `m` with a geom of `arm`'s bodies or of `carried_body` (-1: none).
  ArmCollider(const mjModel* m, const ArmChain& arm, int carried_body = -1);

  /// The number of contacts deeper than `tolerance_m` in `d` (after its kinematics) that a
  /// pose may not have: those of the arm with anything but `ignore_body` (the object in the
  /// hand; -1: none), plus, with a carried body, those of the carried body with anything but
  /// the arm. With several bodies to ignore, the smallest count of the arm's contacts ignoring
  /// one of them (a contact no single ignore explains counts). With `clearance_m` > 0, the arm
  /// must also keep that far from every movable object (a body with a free joint) but
  /// `clearance_exempt` and the carried body: closer counts as a contact.
  int Count(const mjData* d, const std::vector<int>& ignore_bodies, double tolerance_m,
            double clearance_m = 0, int clearance_exempt = -1) const;

  /// The geom pairs checked (for tests).
  int num_pairs() const { return static_cast<int>(pairs_.size()); }

 private:
  struct Pair {
    int g1, g2;  ///< in the order MuJoCo passes them (type of g1 <= type of g2)
    int b1, b2;
    bool arm1, arm2;
    mjtNum margin;
    int movable = -1;  ///< the other body when it is a movable object and the pair has the arm
  };
  const mjModel* m_;
  int carried_;
  std::vector<Pair> pairs_;
};

}  // namespace simhuman::control::manip
