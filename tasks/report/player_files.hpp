// The report's 3D players: each scene's run as DIR/<scene>.player.js (tasks/player_data.hpp),
// and the player's bundle copied beside the page.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tasks/report/inventory.hpp"
#include "util/result.hpp"

namespace tasks::report {

/// The player's bundle, in the assets (player/CMakeLists.txt), copied beside the page.
inline constexpr const char* kPlayerBundle = "rattleback-player.js";

/// What a scene's player replays: nothing (no player), its run, or its run and the body spun
/// the other way (tasks::otherSpinOf).
enum class PlayerRuns { None, One, BothSpins };

/// A scene with a player: its id (the scene's name) and what it replays.
struct PlayerPlace {
  std::string id;
  PlayerRuns runs = PlayerRuns::One;
};

/// Writes the bundle and each scene's run that can be replayed; returns the scenes with a
/// player (none when the build made no bundle). What is left out and why is added to `notes`.
rb::Result<std::vector<PlayerPlace>> writePlayers(const fs::path& dir, const Folder& folder,
                                                  std::vector<std::string>& notes);

}  // namespace tasks::report
