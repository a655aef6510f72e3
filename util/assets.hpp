// Where the assets are (shaders, the font list, the report's player): found at run time from
// the file this code is linked into, so that an installed tree can move.
#pragma once

#include <string>

namespace rb {

/// 1. $RATTLEBACK_ASSETS when set; 2. <folder of the program or module>/../share/rattleback
/// (installed; only this relative path is compiled in); 3. the build tree's copy in
/// <build>/share/rattleback beside <build>/app, <build>/tests, <build>/bench, and for the
/// Python package <build>/python/rattleback or <prefix>/lib/python3/dist-packages/rattleback.
std::string assetsDir();

}  // namespace rb
