// cemv_diff_long --long MINUTES [--seed S]: the differential test for as long
// as asked (not part of make test); prints the cycles checked.
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include "tests/encoder/diff_support.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"

int main(int argc, char** argv) {
  double minutes = 1;
  std::uint64_t seed = 1'000'000;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--long") == 0) minutes = std::atof(argv[i + 1]);
    else if (std::strcmp(argv[i], "--seed") == 0) seed = std::strtoull(argv[i + 1], nullptr, 10);
    else {
      std::cerr << "usage: cemv_diff_long --long MINUTES [--seed S]\n";
      return 2;
    }
  }
  using clock = std::chrono::steady_clock;
  auto end = clock::now() + std::chrono::duration<double, std::ratio<60>>(minutes);
  std::uint64_t matrices = 0, cycles = 0;
  while (clock::now() < end) {
    cemv::testsupport::MatrixOptions opt;
    opt.max_causes = 4 + static_cast<int>(seed % 12);
    opt.max_effects = 2 + static_cast<int>(seed % 6);
    auto m = cemv::testsupport::random_matrix(seed, opt);
    auto inputs = cemv::testsupport::random_inputs(m, seed, 1000);
    auto d = cemv::encoder_test::compare(m, inputs);
    if (d) {
      std::cout << cemv::encoder_test::report(seed, m, inputs, *d);
      std::cout << "FAILED after " << matrices << " matrices, " << cycles << " cycles\n";
      return 1;
    }
    ++matrices;
    cycles += inputs.size();
    ++seed;
  }
  std::cout << "agreed: " << matrices << " matrices, " << cycles << " cycles checked\n";
  return 0;
}
