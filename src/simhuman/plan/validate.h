#pragma once
/// Checking a Chain of Contacts against a scene and grounding its names.

#include <string>
#include <string_view>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::plan {

/// Checks every step and pair of `chain` against `scene` and grounds the names:
/// - the plan and every step must be non-empty; every pair must pass CheckPairShape();
/// - `agent` must be < scene.num_agents();
/// - `object` must be an object id of the scene (exact match);
/// - `part` (unless "none") is matched against the object's part names and aliases, first
///   exactly (case-insensitive, '_' = ' ', digits kept: a catalog can tell "arm sofa style44"
///   from "arm sofa style48" by aliases), then by CatalogObject::FindPart()'s rule (trailing
///   ScenePlan digits ignored: "mattress25", "seat soft surface42"). It is replaced by the
///   canonical part name. A name that matches several parts at the deciding stage is an error
///   (ambiguous). If no part matches but the name is a body joint ("left knee", "pelvis"),
///   `part_joint` is set and `part` becomes the canonical joint name: the target is that body
///   point of the same agent. An object part wins over a body joint of the same name.
/// - a carry step (`carry` set) is grounded by GroundCarryStep() (carry.h), against the scene as
///   earlier carry steps left it (objects at their goals);
/// Never substitutes a default. Errors are InvalidArgument, start with "<source>: <JSON pointer
/// of the field>: " and list the valid names (objects of the scene, parts of the object, agent
/// range). On error `chain` is left unchanged; on success it is grounded in place.
absl::Status ValidateAndGround(ContactChain& chain, const core::SceneCatalog& scene);

/// ParseContactChain() followed by ValidateAndGround().
absl::StatusOr<ContactChain> ParseAndGround(std::string_view text, std::string_view source,
                                            const core::SceneCatalog& scene);

/// LoadContactChainFile() followed by ValidateAndGround().
absl::StatusOr<ContactChain> LoadAndGroundFile(const std::string& path,
                                               const core::SceneCatalog& scene);

}  // namespace simhuman::plan
