// Kane & Levinson's (1982) ellipsoid from the one file that holds it, scenes/kane-levinson.yaml
// (their body and frame conversion are documented there), with keys set over it as --set sets
// them: the tests that need the published body read it from there rather than copy it.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/loader.hpp"

namespace testing_support {

inline sim::SceneSpec kaneLevinson(const std::vector<scene::KeyValue>& values = {}) {
  const std::string path = std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/kane-levinson.yaml";
  auto text = scene::readSceneFile(path);
  if (!text) {
    ADD_FAILURE() << text.error().text();
    return {};
  }
  auto loaded = scene::loadWithValues(text.value(), path, values, "kaneLevinson");
  if (!loaded) {
    ADD_FAILURE() << loaded.error().text();
    return {};
  }
  return loaded->spec;
}

}  // namespace testing_support
