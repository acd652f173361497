// Not in make test: writes the benchmark's generated matrix
// (testsupport::big_matrix(SEED), default 1) as cemv-matrix/1 JSON, so that
// the CLI (cemv testgen, cemv check) can be run on it by hand.
#include <cstdlib>
#include <iostream>

#include "formats/matrix_json.hpp"
#include "tests/support/random_matrix.hpp"

int main(int argc, char** argv) {
  const std::uint64_t seed = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1;
  std::cout << cemv::formats::to_canonical_json(cemv::testsupport::big_matrix(seed));
}
