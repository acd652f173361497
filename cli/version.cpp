#include "cli/version.hpp"

#include "cemv_build_version.h"  // generated at every build (cli/CMakeLists.txt)

namespace cemv::cli {

const char* build_version() { return CEMV_BUILD_VERSION; }

}  // namespace cemv::cli
