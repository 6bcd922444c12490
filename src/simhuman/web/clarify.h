#pragma once
/// Taking the answer to a planner's clarifying question ("Which box: the one on the brown table
/// (box001), ... or the one at (1.10, 0.15) (box004)?"): the answer picks one candidate and the
/// command is asked again naming it. Text only: no MuJoCo.

#include <string>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"

namespace simhuman::web {

/// The command `command` again with the object the user chose in `answer` to `question` named by
/// its id ("touch the box" + "the one on the brown table" -> "touch box001"). The answer may be
/// the candidate's id, its description or a part of it ("on the brown table"), or its number in
/// the list ("2"). Errors: InvalidArgument when the answer matches no candidate or several
/// (listing them), or when the question lists no candidates "(id)" of `catalog`.
core::StatusOr<std::string> AnswerQuestion(const std::string& command, const std::string& question,
                                           const std::string& answer,
                                           const core::SceneCatalog& catalog);

}  // namespace simhuman::web
