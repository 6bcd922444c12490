#include "simhuman/control/manip/arm_collision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "simhuman/control/manip/grasp_task.h"
#include "simhuman/core/rng.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/seating.h"
#include "simhuman/world/sim_world.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::control::manip {
namespace {

// what ArmCollider::Count stands for, from mj_collision over the whole model
int CountFromAllContacts(const mjModel* m, mjData* d, const ArmChain& arm,
                         const std::vector<int>& ignores, int carried, double tol) {
  mj_collision(m, d);
  auto in_arm = [&](int b) {
    return std::find(arm.bodies.begin(), arm.bodies.end(), b) != arm.bodies.end();
  };
  const std::vector<int> slots = ignores.empty() ? std::vector<int>{-1} : ignores;
  int best = 1 << 30, carried_count = 0;
  for (int ignore : slots) {
    int n = 0;
    for (int c = 0; c < d->ncon; ++c) {
      const mjContact& con = d->contact[c];
      if (con.dist > -tol) continue;
      const int b1 = m->geom_bodyid[con.geom1], b2 = m->geom_bodyid[con.geom2];
      if ((in_arm(b1) || in_arm(b2)) && b1 != ignore && b2 != ignore) ++n;
    }
    best = std::min(best, n);
  }
  for (int c = 0; c < d->ncon && carried >= 0; ++c) {
    const mjContact& con = d->contact[c];
    if (con.dist > -tol) continue;
    const int b1 = m->geom_bodyid[con.geom1], b2 = m->geom_bodyid[con.geom2];
    if ((b1 == carried || b2 == carried) && !in_arm(b1) && !in_arm(b2)) ++carried_count;
  }
  return best + carried_count;
}

// a random arm pose, and the object (its free joint at `obj_qpos`) somewhere around the palm:
// into the hand, the table or another object
void RandomArmAndObject(const mjModel* m, mjData* d, const ArmChain& arm, int obj_qpos,
                        core::Rng& rng) {
  Eigen::VectorXd q(ArmChain::kDofs);
  for (int i = 0; i < ArmChain::kDofs; ++i) q[i] = rng.Uniform(arm.lo[i], arm.hi[i]);
  arm.Set(d, q);
  mj_kinematics(m, d);
  for (int i = 0; i < 3; ++i) {
    d->qpos[obj_qpos + i] = d->site_xpos[3 * arm.palm_site + i] + rng.Uniform(-0.12, 0.12);
  }
  mj_kinematics(m, d);
}

// a generated tabletop scene with its seated human, and its task object's body and qpos address
struct TableScene {
  std::unique_ptr<world::SimWorld> world;
  GraspIndex gi;
  int obj = -1, obj_qpos = -1;
};
std::optional<TableScene> MakeTableScene(uint64_t seed, const char* kind) {
  auto ts = world::GenerateTabletop(seed, kind);
  auto catalog = ts.ok() ? world::BuildCatalog(ts->scene) : ts.status();
  auto human = catalog.ok() ? world::AgentFromHuman(ts->scene.humans[0], 0, *catalog)
                            : core::StatusOr<world::AgentSpec>(catalog.status());
  if (!human.ok()) {
    ADD_FAILURE() << human.status();
    return std::nullopt;
  }
  auto w = world::SimWorld::Create(*catalog, {*human}, world::DexterousModelOptions());
  if (!w.ok()) {
    ADD_FAILURE() << w.status();
    return std::nullopt;
  }
  TableScene s;
  s.world = *std::move(w);
  s.gi = *MakeGraspIndex(*s.world, 0, true);
  const mjModel* m = s.world->model();
  s.obj = mj_name2id(m, mjOBJ_BODY, world::ObjectBodyName(ts->task.object_id).c_str());
  s.obj_qpos = m->jnt_qposadr[m->body_jntadr[s.obj]];
  return s;
}

TEST(ArmCollisionTest, CountsWhatMjCollisionFindsForTheArmAndACarriedObjectIntegration) {
  for (uint64_t seed : {3u, 8u}) {
    const std::optional<TableScene> scene = MakeTableScene(seed, seed % 2 ? "stack" : "place");
    ASSERT_TRUE(scene);
    const mjModel* m = scene->world->model();
    mjData* d = scene->world->data();
    const ArmChain& arm = scene->gi.arm;
    const int obj = scene->obj, obj_qpos = scene->obj_qpos;
    const ArmCollider alone(m, arm), carrying(m, arm, obj);
    EXPECT_GT(carrying.num_pairs(), alone.num_pairs());
    core::Rng rng(seed);
    int touching = 0, carried_touching = 0;
    for (int k = 0; k < 400; ++k) {
      RandomArmAndObject(m, d, arm, obj_qpos, rng);
      for (double tol : {0.0, 0.002}) {
        const int a = alone.Count(d, {}, tol);
        EXPECT_EQ(a, CountFromAllContacts(m, d, arm, {}, -1, tol)) << "pose " << k;
        const int c = carrying.Count(d, {obj}, tol);
        EXPECT_EQ(c, CountFromAllContacts(m, d, arm, {obj}, obj, tol)) << "pose " << k;
        touching += a > 0;
        carried_touching += c > a;
      }
    }
    // the poses cover both cases
    EXPECT_GT(touching, 100);
    EXPECT_GT(carried_touching, 50);
  }
}

// The clearance from movable objects: the same verdict as mj_collision on a copy of the model
// whose movable objects' geoms carry the clearance as their margin, counting those objects'
// contacts with the arm closer than the clearance (and the exempt object's only when they touch).
TEST(ArmCollisionTest, KeepsTheClearanceFromMovableObjectsThatMjCollisionMeasuresIntegration) {
  const std::optional<TableScene> scene = MakeTableScene(5, "place");
  ASSERT_TRUE(scene);
  const mjModel* m = scene->world->model();
  mjData* d = scene->world->data();
  const ArmChain& arm = scene->gi.arm;
  const int obj = scene->obj, obj_qpos = scene->obj_qpos;
  constexpr double kClear = 0.02, kTol = 0.002;
  auto movable = [&](int b) {
    return m->body_jntnum[b] > 0 && m->jnt_type[m->body_jntadr[b]] == mjJNT_FREE;
  };
  // per exempt body (-1, obj): the model with the others' margins inflated
  using ModelPtr = std::unique_ptr<mjModel, void (*)(mjModel*)>;
  std::vector<ModelPtr> inflated;
  for (int exempt : {-1, obj}) {
    inflated.emplace_back(mj_copyModel(nullptr, m), mj_deleteModel);
    for (int g = 0; g < m->ngeom; ++g) {
      const int b = m->geom_bodyid[g];
      if (movable(b) && b != exempt) inflated.back()->geom_margin[g] += kClear;
    }
  }
  std::unique_ptr<mjData, void (*)(mjData*)> dd(mj_makeData(m), mj_deleteData);
  auto in_arm = [&](int b) {
    return std::find(arm.bodies.begin(), arm.bodies.end(), b) != arm.bodies.end();
  };
  const ArmCollider collider(m, arm);
  core::Rng rng(5);
  int kept_apart = 0;
  for (int k = 0; k < 300; ++k) {
    RandomArmAndObject(m, d, arm, obj_qpos, rng);
    for (int exempt : {-1, obj}) {
      const mjModel* mi = inflated[exempt < 0 ? 0 : 1].get();
      mju_copy(dd->qpos, d->qpos, m->nq);
      mj_kinematics(mi, dd.get());
      mj_collision(mi, dd.get());
      int want = 0;
      for (int c = 0; c < dd->ncon; ++c) {
        const mjContact& con = dd->contact[c];
        const int b1 = m->geom_bodyid[con.geom1], b2 = m->geom_bodyid[con.geom2];
        if (!in_arm(b1) && !in_arm(b2)) continue;
        const int other = in_arm(b1) ? b2 : b1;
        const bool clear = !in_arm(other) && movable(other) && other != exempt;
        want += clear ? con.dist < kClear : con.dist <= -kTol;
      }
      const int got = collider.Count(d, {}, kTol, kClear, exempt);
      // a margin can change how many points MuJoCo's narrow phase gives a pair, so the counts may
      // differ by a point; whether a pose is free may not
      EXPECT_EQ(got > 0, want > 0) << "pose " << k << " exempt " << exempt;
      EXPECT_NEAR(got, want, 0.2 * want + 1) << "pose " << k << " exempt " << exempt;
      kept_apart += exempt < 0 && got > collider.Count(d, {}, kTol);
    }
  }
  EXPECT_GT(kept_apart, 20);  // the clearance counts poses that do not touch
}

// A carried object keeps the clearance from the other movable objects too (it swung into a
// stack's bottom object on the way over it), and only the clearance: just apart, it is free of
// contacts.
TEST(ArmCollisionTest, ACarriedObjectKeepsTheClearanceFromOtherObjectsIntegration) {
  const std::optional<TableScene> scene = MakeTableScene(3, "stack");
  ASSERT_TRUE(scene);
  const mjModel* m = scene->world->model();
  mjData* d = scene->world->data();
  const int obj = scene->obj;
  // another object on the table: a body of its own with a free joint
  int other = -1;
  for (int b = 1; b < m->nbody && other < 0; ++b) {
    const bool free = m->body_jntnum[b] > 0 && m->jnt_type[m->body_jntadr[b]] == mjJNT_FREE;
    if (free && b != obj && m->body_parentid[b] == 0 &&
        std::string(m->names + m->name_bodyadr[b]).rfind("obj/", 0) == 0) {
      other = b;
    }
  }
  ASSERT_GE(other, 0);
  const int other_qpos = m->jnt_qposadr[m->body_jntadr[other]];
  constexpr double kClear = 0.02, kTol = 0.002;
  const ArmCollider carrying(m, scene->gi.arm, obj);
  // the carried object over the other one, raised until it no longer touches it
  auto put_at = [&](double dz) {
    for (int i = 0; i < 2; ++i) d->qpos[scene->obj_qpos + i] = d->qpos[other_qpos + i];
    d->qpos[scene->obj_qpos + 2] = d->qpos[other_qpos + 2] + dz;
    mj_kinematics(m, d);
  };
  double apart = -1;
  for (double dz = 0.05; dz < 0.4; dz += 0.001) {
    put_at(dz);
    if (carrying.Count(d, {obj}, kTol) == 0) {
      apart = dz;
      break;
    }
  }
  ASSERT_GT(apart, 0);
  put_at(apart + 0.01);
  EXPECT_EQ(carrying.Count(d, {obj}, kTol), 0);
  EXPECT_GT(carrying.Count(d, {obj}, kTol, kClear), 0);
  EXPECT_EQ(carrying.Count(d, {obj}, kTol, kClear, other), 0);  // an exempt object is exempt
  put_at(apart + kClear + 0.01);
  EXPECT_EQ(carrying.Count(d, {obj}, kTol, kClear), 0);
}

}  // namespace
}  // namespace simhuman::control::manip
