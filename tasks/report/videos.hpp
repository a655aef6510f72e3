// A scene's videos on the report page, each captioned with what the theory predicts for its
// direction and, where simulate's run was spun the same way, what that run did: the theory is
// linear and holds near upright, and a body that loses no energy can reverse both ways, so the
// page never says what the videos show without a run that measured it.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>

#include "tasks/report/inventory.hpp"
#include "tasks/report/sidecars.hpp"

namespace tasks::report {

/// The scene's videos: the preferred and reversed pair, the clockwise and counter-clockwise
/// pair, a video alone, and a link to both side by side. `theory` is analyze --json's.
void writeVideos(std::ostream& out, const SceneFiles& f,
                 const std::optional<nlohmann::json>& theory, const std::optional<RunRecord>& run);

}  // namespace tasks::report
