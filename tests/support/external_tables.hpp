// The published LSST TMA tables, read where they are (CEMV_LSST_DIR), never
// copied into the project (they carry no licence). A test that needs one asks
// for it here: when it is absent the test process exits 77, which CTest reports
// as "Skipped" (the discovered tests carry SKIP_RETURN_CODE 77), after saying
// how to provide it; with CEMV_REQUIRE_EXTERNAL=1 (CI) it fails instead.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace cemv::test {

inline constexpr int kExternalSkipCode = 77;

inline std::filesystem::path lsst_table(const std::filesystem::path& dir, const std::string& name) {
  const std::filesystem::path path = dir / name;
  if (std::filesystem::is_regular_file(path)) return path;
  std::printf("waits for the published LSST tables: %s not in %s; run scripts/fetch-external, or configure "
              "with -DCEMV_LSST_DIR=DIR (README, \"Tests that read published data\")\n",
              name.c_str(), dir.string().c_str());
  std::fflush(stdout);
  const char* required = std::getenv("CEMV_REQUIRE_EXTERNAL");
  if (required && std::strcmp(required, "1") == 0) {
    std::fprintf(stderr, "error: CEMV_REQUIRE_EXTERNAL=1: the published tables are required here\n");
    std::exit(1);
  }
  std::exit(kExternalSkipCode);
}

}  // namespace cemv::test
