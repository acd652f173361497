// Seeded runs of a product of plc_check's (correspondence.hpp filters its
// candidates with the states they reach), and the first run on which the
// output's relation breaks, when one does: a difference found without a
// solver, made as short as deleting scans keeps it. Concrete, on the
// encoder's evaluator of the product's formulas; a fixed number of runs from a
// fixed seed, so the same problem gives the same states and the same run.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "checker/prover.hpp"
#include "encoder/evaluate.hpp"

namespace cemv::plc_check {

struct SamplingOptions {
  int runs = 64;
  int cycles_per_run = 400;
  unsigned seed = 1;
  // The plant at rest, by input name (the matrix's scenario defaults): every
  // other run starts there and changes one to three inputs a stretch, as a
  // test engineer does, which reaches the difference that needs everything
  // else quiet (one transmitter alone over its limit through a delay). An
  // input it does not name rests at 0; none given: every run is random.
  std::function<std::optional<checker::Value>(const std::string&)> rest;
  // Cones (ascending state-variable indices; plc_check/cones.hpp): kept are
  // the distinct states of each cone's variables alone, at most `max_states`
  // of each (the first reached), not every state of the product, whose
  // distinct states are nearly all the scans of a big product's runs (a
  // 128 x 128 x 1024 matrix's generated program: 25,600 states of thousands
  // of variables). Empty: every distinct state of the product, unbounded.
  std::vector<std::vector<std::size_t>> cones;
  // 0: no state kept, only which variables change (Samples::unchanged) and
  // a difference.
  std::size_t max_states = 4096;
  // Runs that trip causes together, one run each after the others, as an
  // acceptance test does: an effect voted 11oo11 is never tripped by
  // independent draws, so its output delay never runs in them and nothing
  // relates the two sides' timers; an override is started only by its
  // command or reset tag while the effect is active. A trip's inputs (by
  // name, over the rest) but those the pulses set (a reset tag's edge needs
  // its source at rest before) are held `hold` scans; each pulse (what
  // overrides or resets the effect) is set over them for `pulse` scans and
  // they are held again; then the whole trip is held `hold` scans, and one
  // to three inputs change a stretch around it.
  // Half-way every input goes back to rest and the pulses are repeated
  // there (the latches reset), and the changes go on around the rest.
  struct Trip {
    std::map<std::string, checker::Value> inputs;
    int hold = 1;
    std::vector<std::map<std::string, checker::Value>> pulses;
    int pulse = 1;
  };
  std::vector<Trip> trips;
  int cycles_per_trip = 120;
};

// The distinct states of one cone's variables (values in the cone's order),
// each with the number of distinct states of the product it stands for.
struct ConeStates {
  std::vector<std::size_t> vars;
  std::vector<std::vector<encoder::Evaluator::Value>> states;
  std::vector<std::size_t> weights;
};

struct Samples {
  // Distinct states reached (values by TransitionSystem::statevars index),
  // the initial state first; empty when the evaluator does not take an
  // operator of the formulas.
  std::vector<std::vector<encoder::Evaluator::Value>> states;
  // With SamplingOptions::cones: each cone's states instead (`states` empty).
  std::vector<ConeStates> cones;
  // By state variable: every sampled state holds its initial value there.
  // Empty when nothing was sampled.
  std::vector<char> unchanged;
  // A run from the initial state whose every scan keeps the constraints and
  // the assumption and whose last scan breaks `good`; sampling stops there.
  std::optional<checker::Trace> violation;
};

// Inputs drawn from the numerals of the formulas (the limits, as ordered
// integers once reduced) and one either side, changed at the start of a
// stretch (each with probability 1/2, or one to three from rest), held for as
// many scans as a numeral or one or two more (a timer runs out, or stops one
// scan short). In the random runs (not those from rest) an integer input
// is drawn three times in four among the numerals it is itself compared
// with, and one either side, from a stream of its own (the runs from rest
// draw as without it). A draw that breaks the constraints or the assumption
// is drawn again. Then the trips' runs (SamplingOptions::trips), from a
// stream of their own.
Samples sample(const checker::SafetyProblem& p, const SamplingOptions& o = {});

}  // namespace cemv::plc_check
