// The exact build of this binary: the project version and the git commit it
// was built from, e.g. "0.1.0+git412.g1a2b3c4d5e" (cmake/build_version.cmake),
// as `cemv --version` prints it and the Debian package is versioned. The
// result cache (cemv check --cache) keys on it.
#pragma once

namespace cemv::cli {

const char* build_version();

}  // namespace cemv::cli
