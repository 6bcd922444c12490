#pragma once
/// UniHSI's ScenePlan medium and hard levels (Section 4.3, Appendix B, Tables 6-7) as seeded
/// episode generators in furnished rooms (world/room.h), the human starting 1-6 m from the first
/// object at a random heading:
///  - medium: more than 3 steps on one object (a chair, armchair, sofa, stool or bed): walk to
///    it, sit (or sit on the edge and lie), then 2-4 of the object's poses (UniHSI Tables 8-9:
///    hands or elbows on the armrests, hands on the knees or stomach, a foot on a knee, lean
///    forward or back; on a bed knees up, hands on the pillow, on a side, head up), a pose
///    sometimes after standing up and sitting again;
///  - hard: more than 3 steps over 2-3 objects: a desk (sit on its chair, then both hands on the
///    laptop's keyboard while seated: two objects at once, Table 7), then a bed (lie) and/or a
///    sofa or armchair, with stand-up and walk steps between them.
/// Plans follow the corpus conventions (docs/FORMATS.md); the suites live in eval/suites.cc.

#include "simhuman/core/rng.h"
#include "simhuman/core/status.h"
#include "simhuman/eval/suites.h"

namespace simhuman::eval {

/// Draws one sceneplan-mid episode.
core::Status MakeScenePlanMid(core::Rng& rng, EpisodeSpec* out);

/// Draws one sceneplan-hard episode.
core::Status MakeScenePlanHard(core::Rng& rng, EpisodeSpec* out);

}  // namespace simhuman::eval
