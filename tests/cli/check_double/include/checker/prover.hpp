// TEST DOUBLE of checker/prover.hpp: only the InternalError the CLI catches,
// declared as the real header declares it (see ../../README.md).
#pragma once

#include <stdexcept>

namespace cemv::checker {

class InternalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cemv::checker
