// Internal to testgen/: test steps phrased for the field (docs/testgen.md,
// "Checklist"): "Set LT_100A to 95 % (limit 90, high)", "Wait 2.0 s",
// "Press reset for effect 1 CLOSE_XV101".
#pragma once

#include <cstdint>
#include <string>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::testgen::detail {

std::string phrase_input(const model::Matrix& m, const model::InputTag& tag, const model::TagValue& before,
                         const model::TagValue& now);
std::string phrase_command(const model::Matrix& m, const model::Command& c);
std::string phrase_duration(std::uint64_t ms);
// "cause 1 LT100_HH active: yes", "XV_101 = 0", "cause 1 LT100_HH voting: 1oo2".
std::string phrase_observation(const model::Matrix& m, const model::Observable& o, int value);

}  // namespace cemv::testgen::detail
