// Analog values people can read. A counterexample found on the reduced
// problem (analog inputs as ordered integers, checker/reduce.hpp) comes back
// with the float next to a limit: 90.0000076 for "just over 90", 2.8e-42
// for "small". round_values puts each analog input's value, over each stretch
// of cycles that holds it, at the roundest number that keeps the violation:
// whole numbers first, then one, two and three decimals, nearest first. It
// is concrete (the encoding's own evaluator; microseconds a try) and keeps
// the trace's length and last cycle; a value no rounder number replaces
// stays as it was.
#pragma once

#include "checker/prover.hpp"

namespace cemv::checker {

// `cex` violates `problem` (as built, with Float32 inputs) in its last cycle;
// so does the answer. A problem the evaluator cannot run gives `cex` back.
Trace round_values(const SafetyProblem& problem, const Trace& cex);

}  // namespace cemv::checker
