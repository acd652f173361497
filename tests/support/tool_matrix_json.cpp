// `cemv_matrix_json N [SEED]`: the generated N x N matrix of the benchmarks
// and the time-limit sweeps (testsupport::square_matrix; N = 128 is the
// 128 x 128 x 1024 big_matrix) as cemv-matrix/1 JSON on standard output, so
// that the command line can be run and timed on it (bench/README.md).
#include <cstdlib>
#include <iostream>

#include "formats/matrix_json.hpp"
#include "tests/support/random_matrix.hpp"

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 16;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  if (n < 1 || n > 128) {
    std::cerr << "usage: cemv_matrix_json N [SEED]   (1 <= N <= 128)\n";
    return 2;
  }
  std::cout << cemv::formats::to_canonical_json(cemv::testsupport::square_matrix(n, seed));
  return std::cout ? 0 : 2;
}
