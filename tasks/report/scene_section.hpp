// A scene's section of the report page: what was made from it (videos, stills, plots), its
// 3D player, the theory beside what the run measured, and its other runs.
#pragma once

#include <ostream>
#include <string>

#include "tasks/report/inventory.hpp"

namespace tasks::report {

/// The section of the scene `name`, whose files are `f` in `dir`; `player`: the scene has a
/// 3D player (its DIR/<name>.player.js is written).
void writeScene(std::ostream& out, const fs::path& dir, const std::string& name,
                const SceneFiles& f, bool player);

}  // namespace tasks::report
