/// @file build_info.hpp
/// @brief What a build was made from. Defined in a source file the build
/// generates (cmake/ToolkitRevision.cmake), so a new commit recompiles only it.
#pragma once

namespace tk::cli {

/// The project's version, "X.Y.Z".
const char* toolkit_version();
/// `git describe --always --dirty` of the source tree at build time
/// ("unknown" outside a git checkout).
const char* toolkit_revision();

}  // namespace tk::cli
