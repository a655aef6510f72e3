// A scene's section of the report page: what was made from it (videos, stills, plots), its
// 3D player, the theory beside what the run measured, and its other runs.
#pragma once

#include <ostream>
#include <string>

#include "tasks/report/inventory.hpp"
#include "tasks/report/player_files.hpp"

namespace tasks::report {

/// The section of the scene `name`, whose files are `f` in `dir`; `player`: what the scene's
/// 3D player replays (its DIR/<name>.player.js is written), None where it has none.
void writeScene(std::ostream& out, const fs::path& dir, const std::string& name,
                const SceneFiles& f, PlayerRuns player);

}  // namespace tasks::report
