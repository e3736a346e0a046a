// The program's version and the source it was built from (git describe at
// build time; "unknown" outside a git checkout). Generated into
// build/generated/version.cpp by cmake/version.cmake at every build, rewritten
// only when it changes, so a commit recompiles one file.
#pragma once

namespace bx {

const char* bestiary_version();  ///< e.g. "0.1.0"
const char* bestiary_git();      ///< e.g. "4de5742" or "4de5742-dirty"

}  // namespace bx
