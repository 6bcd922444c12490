#include "simhuman/control/manip/arm_collision.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "simhuman/core/check.h"

namespace simhuman::control::manip {
namespace {

// MuJoCo's body filter: geoms of one body, of bodies welded together, of a body and its parent
// (unless the model turns that filter off) or of an excluded body pair never collide
bool BodiesFiltered(const mjModel* m, int b1, int b2) {
  if (b1 == b2) return true;
  const int w1 = m->body_weldid[b1], w2 = m->body_weldid[b2];
  if (w1 == w2) return true;
  const int p1 = m->body_weldid[m->body_parentid[w1]], p2 = m->body_weldid[m->body_parentid[w2]];
  if (!(m->opt.disableflags & mjDSBL_FILTERPARENT) && w1 != 0 && w2 != 0 &&
      (w1 == p2 || w2 == p1)) {
    return true;
  }
  const int lo = std::min(b1, b2), hi = std::max(b1, b2);
  const int signature = ((lo + 1) << 16) + hi + 1;
  for (int e = 0; e < m->nexclude; ++e) {
    if (m->exclude_signature[e] == signature) return true;
  }
  return false;
}

// whether geom `g`'s bounding sphere (radius `r`, inflated by `margin`) lies clear of box
// `box`: then no contact between them is possible (a cheap test before the narrow phase, which
// for an arm capsule near the table's board costs a hundred times more)
bool ClearOfBox(const mjModel* m, const mjData* d, int box, int g, mjtNum r, mjtNum margin) {
  mjtNum rel[3], local[3];
  mju_sub3(rel, d->geom_xpos + 3 * g, d->geom_xpos + 3 * box);
  mju_mulMatTVec(local, d->geom_xmat + 9 * box, rel, 3, 3);
  mjtNum out2 = 0;
  for (int k = 0; k < 3; ++k) {
    const mjtNum over = std::abs(local[k]) - m->geom_size[3 * box + k];
    if (over > 0) out2 += over * over;
  }
  const mjtNum reach = r + margin;
  return out2 > reach * reach;
}

}  // namespace

ArmCollider::ArmCollider(const mjModel* m, const ArmChain& arm, int carried_body)
    : m_(m), carried_(carried_body) {
  if (m->opt.disableflags & (mjDSBL_CONTACT | mjDSBL_CONSTRAINT)) return;
  std::vector<bool> in_arm(m->nbody, false);
  for (int b : arm.bodies) in_arm[b] = true;
  std::vector<bool> parent(m->nbody, false);
  for (int b = 1; b < m->nbody; ++b) parent[m->body_parentid[b]] = true;
  auto checked = [&](int g) {
    const int b = m->geom_bodyid[g];
    return in_arm[b] || b == carried_body;
  };
  for (int g1 = 0; g1 < m->ngeom; ++g1) {
    for (int g2 = g1 + 1; g2 < m->ngeom; ++g2) {
      if (!checked(g1) && !checked(g2)) continue;
      const bool types = (m->geom_contype[g1] & m->geom_conaffinity[g2]) ||
                         (m->geom_contype[g2] & m->geom_conaffinity[g1]);
      const int b1 = m->geom_bodyid[g1], b2 = m->geom_bodyid[g2];
      if (!types || BodiesFiltered(m, b1, b2)) continue;
      Pair p{g1, g2, b1, b2, in_arm[b1], in_arm[b2], 0};
      // mj_collideGeoms: the function of the lower geom type first
      if (m->geom_type[g1] > m->geom_type[g2]) {
        std::swap(p.g1, p.g2);
        std::swap(p.b1, p.b2);
        std::swap(p.arm1, p.arm2);
      }
      if (!mjCOLLISIONFUNC[m->geom_type[p.g1]][m->geom_type[p.g2]]) continue;
      // the body the arm or the carried object must keep clear of: a movable object (a free
      // joint; for the carried object only a body of its own, not a humanoid's root)
      const bool arm_pair = in_arm[b1] || in_arm[b2];
      const int other = arm_pair             ? (in_arm[b1] ? b2 : b1)
                        : b1 == carried_body ? b2
                        : b2 == carried_body ? b1
                                             : -1;
      if (other >= 0 && other != carried_body && (arm_pair || !parent[other]) &&
          m->body_jntnum[other] > 0 && m->jnt_type[m->body_jntadr[other]] == mjJNT_FREE) {
        p.movable = other;
      }
      p.margin = (m->opt.enableflags & mjENBL_OVERRIDE)
                     ? m->opt.o_margin
                     : std::max(m->geom_margin[g1], m->geom_margin[g2]);
      pairs_.push_back(p);
    }
  }
}

int ArmCollider::Count(const mjData* d, const std::vector<int>& ignore_bodies, double tolerance_m,
                       double clearance_m, int clearance_exempt) const {
  // the arm's contacts ignoring each body in turn (one count when none is ignored)
  constexpr int kMaxIgnores = 8;
  SH_CHECK(ignore_bodies.size() <= kMaxIgnores, "ArmCollider::Count: at most 8 bodies to ignore");
  int arm_count[kMaxIgnores] = {0};
  const int slots = std::clamp(static_cast<int>(ignore_bodies.size()), 1, kMaxIgnores);
  int carried_count = 0;
  mjContact con[mjMAXCONPAIR];
  for (const Pair& p : pairs_) {
    const mjtNum r1 = m_->geom_rbound[p.g1], r2 = m_->geom_rbound[p.g2];
    const bool keep_clear = clearance_m > 0 && p.movable >= 0 && p.movable != clearance_exempt;
    const mjtNum margin = keep_clear ? p.margin + clearance_m : p.margin;
    if (r1 > 0 && r2 > 0) {
      // mj_collideGeoms' bounding-sphere test
      const mjtNum* x1 = d->geom_xpos + 3 * p.g1;
      const mjtNum* x2 = d->geom_xpos + 3 * p.g2;
      const mjtNum dx = x1[0] - x2[0], dy = x1[1] - x2[1], dz = x1[2] - x2[2];
      const mjtNum reach = margin + r1 + r2;
      if (dx * dx + dy * dy + dz * dz > reach * reach) continue;
      if (m_->geom_type[p.g2] == mjGEOM_BOX && ClearOfBox(m_, d, p.g2, p.g1, r1, margin)) {
        continue;
      }
    }
    const int n =
        mjCOLLISIONFUNC[m_->geom_type[p.g1]][m_->geom_type[p.g2]](m_, d, con, p.g1, p.g2, margin);
    int deep = 0;
    for (int c = 0; c < n; ++c) {
      deep += keep_clear ? con[c].dist < clearance_m : !(con[c].dist > -tolerance_m);
    }
    if (deep == 0) continue;
    if (p.arm1 || p.arm2) {
      for (int k = 0; k < slots; ++k) {
        const int ignore = ignore_bodies.empty() ? -1 : ignore_bodies[k];
        if (p.b1 != ignore && p.b2 != ignore) arm_count[k] += deep;
      }
    }
    if (carried_ >= 0 && (p.b1 == carried_ || p.b2 == carried_) && !p.arm1 && !p.arm2) {
      carried_count += deep;
    }
  }
  return *std::min_element(arm_count, arm_count + slots) + carried_count;
}

}  // namespace simhuman::control::manip
