// Seeded random scan-cycle inputs (a random scenario) for a matrix: what the
// differential test and the runtime benchmark feed to the runtime and the
// encoder.
#pragma once

#include <cstdint>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"

namespace cemv::testsupport {

// `cycles` frames, each indexed by model::InputTable(m). The first frame holds
// every tag at its non-tripped default (docs/semantics.md S.1), then
// values change after random holds of several cycles:
//  - analog tags take values at and around the thresholds of the causes that
//    read them (limit, limit -/+ hysteresis, prewarning, the neighbouring
//    single-precision values, pairs about `delta` apart), plus random values;
//  - cause input tags sometimes have bad quality;
//  - Boolean control tags (bypass, inhibit, mask, enables) hold for a while,
//    reset and group-deactivation set tags give pulses (rising edges);
//  - operator commands of every model::CommandOp, mostly with valid targets,
//    sometimes invalid ones (unknown ids, a soft bypass where not allowed,
//    unknown tag names) that the runtime must refuse.
// Reproducible: same matrix, seed and count give the same frames everywhere.
std::vector<model::CycleInput> random_inputs(const model::Matrix& m, std::uint64_t seed, int cycles);

// The non-tripped default frame (no commands).
model::CycleInput default_inputs(const model::Matrix& m);

}  // namespace cemv::testsupport
