// Loading a scene with command-line overrides: an override replaces the scene's key before
// compile(), and an error in it is named by its option ("--dt: simulation.dt …").
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>

#include "sim/model.hpp"
#include "sim/spec.hpp"

namespace app {

struct Overrides {
  std::optional<double> duration, dt, playback, spin;
  std::optional<std::string> integrator, view;
  std::optional<std::array<int, 2>> size;
  std::optional<int> fps;
};

/// The compiled model, or the one line to print.
std::variant<sim::Model, std::string> loadScene(const std::string& path, const Overrides& o);

/// For --verbose: one line on stderr with the body, contact, integrator, step and samples.
void describeModel(const sim::Model& model, const std::string& scene, std::int64_t every,
                   const char* what);

/// Parses "1280x720"; false when malformed.
bool parseSize(const std::string& text, std::array<int, 2>& size);

}  // namespace app
