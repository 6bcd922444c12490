#pragma once
/// The LLM planner's prompt, laid out as UniHSI's Table 4 (ICLR 2024): background (objects, their
/// parts, spatial layout, the humans, the 15 body joints), rules, one example, the instruction.
/// The text lives in template files (assets/prompts/: system.txt, user.txt, repair.txt) with
/// {{placeholder}} fields filled from the scene; this file loads and fills them. No MuJoCo here.

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/language/planner.h"

namespace simhuman::language {

/// The three prompt templates. Placeholders are "{{name}}" with a name from
/// PromptPlaceholderNames(); user.txt must contain {{command}} and repair.txt {{errors}}.
struct PromptTemplates {
  std::string system;  ///< the system message: role, rules, output format
  std::string user;    ///< the user message: background, example, the instruction
  std::string repair;  ///< the follow-up user message after a rejected reply
};

/// Names a template may use: objects, parts, layout, humans, joints, contact_types, directions,
/// command, errors.
std::vector<std::string> PromptPlaceholderNames();

/// Reads `dir`/system.txt, user.txt and repair.txt and checks their placeholders. NotFound names
/// a missing file; InvalidArgument names the file and an unknown placeholder (listing the valid
/// ones) or a required one that is missing.
core::StatusOr<PromptTemplates> LoadPromptTemplates(const std::string& dir);

/// Checks placeholders of `templates` as LoadPromptTemplates() does; `source` names them in
/// errors.
core::Status CheckPromptTemplates(const PromptTemplates& templates, std::string_view source);

/// Replaces each {{name}} in `text` by values.at(name), in one pass (replacement text is never
/// scanned again, so a command containing "{{objects}}" stays literal). InvalidArgument naming
/// `source` for a placeholder without a value.
core::StatusOr<std::string> FillTemplate(std::string_view text,
                                         const std::map<std::string, std::string>& values,
                                         std::string_view source);

/// The scene in words, one value per placeholder: "objects", "parts", "layout", "humans",
/// "joints", "contact_types", "directions". Objects are named by id, which is what a plan must
/// use; a human's distance to an object is measured on the floor to the object's footprint
/// (LocalBounds), "close" under 1 m. `agents` empty means one standing human at (0, 0).
std::map<std::string, std::string> DescribeScene(const core::SceneCatalog& scene,
                                                 const std::vector<AgentStart>& agents);

/// The command as quoted data: a JSON string literal (quotes, backslashes and control
/// characters escaped; invalid UTF-8 replaced by U+FFFD), so text in it cannot pose as prompt
/// structure.
std::string QuoteCommand(std::string_view command);

}  // namespace simhuman::language
