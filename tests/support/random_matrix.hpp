// Seeded random cause & effect matrices for tests and benchmarks.
//
// Every matrix is valid (model::validate reports no error; warnings such as
// "S effect without reset tag" are allowed) and the matrices of many seeds
// between them use every option of cemv-matrix/1 (docs/format.md), so the
// runtime, the encoder and their differential test see all of the format.
//
// Reproducible on any machine: the generator uses its own PRNG (splitmix64),
// never std::*_distribution, whose output differs between standard libraries,
// and builds floats only from exact integer-to-float conversions and IEEE
// float division.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::testsupport {

// A small deterministic PRNG (splitmix64, Steele/Lea/Flood 2014): identical
// sequence on every platform and standard library.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  // Uniform integer in [lo, hi] (inclusive; lo <= hi).
  int uniform(int lo, int hi);
  // TRUE with probability p (0..1).
  bool chance(double p);
  // One element of a non-empty vector.
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[static_cast<std::size_t>(uniform(0, static_cast<int>(v.size()) - 1))];
  }

 private:
  std::uint64_t state_;
};

struct MatrixOptions {
  // Sizes are drawn uniformly from [min, max]. 3.4 limits: 128 / 128 / 1024.
  int min_causes = 2, max_causes = 6;
  int min_effects = 1, max_effects = 4;
  // Number of intersections; -1 = about 40 % of the grid (at least one per
  // processed cause and effect), capped at the 1024 limit.
  int intersections = -1;
  // 0 = drawn from {10, 20, 50, 100, 200, 250, 500, 1000} ms (all divide one
  // second, so soft-bypass and override seconds are whole cycles).
  std::uint32_t cycle_ms = 0;

  // Probabilities of the options (per element unless said otherwise).
  double p_analog = 0.4;             // cause input kind analog
  double p_comment = 0.08;           // comment-only cause / effect
  double p_ett = 0.3;                // energize-to-trip tag
  double p_time = 0.5;               // cause time function other than none
  double p_manual_ack = 0.3;         // auto_ack false (none / on_delay only)
  double p_bypass_tag = 0.35;        // hard bypass tag (cause and effect)
  double p_inhibit_tag = 0.3;
  double p_shared_tag = 0.15;        // an input tag also read by an earlier cause
  double p_internal_ref = 0.15;      // a discrete cause tag is Cause[x]/Effect[x]/Effect[x][y]
  double p_cycle_ref = 0.4;          // ...of which: chosen to close a cycle
  double p_control_ref = 0.1;        // a bypass / inhibit / reset tag is an internal reference
  double p_first_out = 0.4;
  double p_xoon = 0.3;               // per effect with >= 2 intersections
  double p_output_delay = 0.3;
  double p_reset_tag = 0.6;
  double p_process_data = 0.3;
  double p_note_intersection = 0.08; // '*' intersections
  double p_secure_write = 0.4;       // per matrix
  double p_group_deactivation = 0.5; // per matrix
  // Per cause input tag and output tag: simulation_allowed false (O.8). 0 by
  // default, so the matrices of earlier versions stay as they were; drawn
  // from a stream of its own.
  double p_simulation_forbidden = 0.0;
};

// A valid random matrix; the same seed and options give the same matrix.
model::Matrix random_matrix(std::uint64_t seed, const MatrixOptions& opt = {});

// 128 causes x 128 effects x 1024 intersections that use every option (every
// entry of feature_names() occurs), for the benchmarks (bench/README.md).
model::Matrix big_matrix(std::uint64_t seed = 1);

// An n x n matrix (about 40 % of the grid, at most 1024 intersections,
// cycle 100 ms) that uses as many options as a matrix of its size can: the
// seed's first derived matrix that uses every entry of feature_names(), else
// the one of 64 that uses the most. For the benchmarks and the time-limit
// sweeps; n = 128 gives big_matrix(seed).
model::Matrix square_matrix(int n, std::uint64_t seed = 1);

// The options a matrix uses, by name, with how often: the test checks that
// across many seeds every name of feature_names() occurs.
std::map<std::string, int> feature_counts(const model::Matrix& m);
const std::vector<std::string>& feature_names();

}  // namespace cemv::testsupport
