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

/// The installed documentation, <assets>/../doc/rattleback (share/doc/rattleback beside
/// share/rattleback), when it is there; empty in a build tree, whose docs are the source's docs/.
std::string docsDir();

/// A page of the documentation as a message cites it: the installed file's path when installed
/// (a user of an installed program has no docs/ folder), else "docs/PAGE" (the source's).
std::string docPage(const std::string& page);

}  // namespace rb
