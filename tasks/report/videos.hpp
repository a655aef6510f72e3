// A scene's videos on the report page, each captioned with what the theory predicts for its
// direction and, where simulate's run was spun the same way, what that run did: the theory is
// linear and holds near upright, and a body that loses no energy can reverse both ways, so the
// page never says what the videos show without a run that measured it.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <vector>

#include "tasks/report/inventory.hpp"
#include "tasks/report/sidecars.hpp"

namespace tasks::report {

/// The scene's videos: the preferred and reversed pair, the clockwise and counter-clockwise
/// pair, a video alone, and a link to both side by side. `theory` is analyze --json's; `runs`
/// are simulate's runs of the scene as it was rendered, the main one first: each video's
/// caption gives what the first run spun its way measured.
void writeVideos(std::ostream& out, const SceneFiles& f,
                 const std::optional<nlohmann::json>& theory, const std::vector<RunRecord>& runs);

}  // namespace tasks::report
