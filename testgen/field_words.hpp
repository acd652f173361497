// Internal to testgen/: the words of the field suite (docs/testgen.md, "Field
// suite"): the values a calibrator sets, outputs in plant words, the Viewer
// indications of manual 10.6, and which status fields a technician sees.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::testgen::detail {

// The analog values of a field test at `resolution`: the trip (the limit plus
// a margin of hysteresis + resolution, rounded away from the limit), the
// healthy value (clearly on the safe side of the hysteresis band and of the
// prewarning, at ten times the resolution), and a value between the
// prewarning and the limit when there is one that the resolution can set.
struct AnalogValues {
  double trip = 0.0, healthy = 0.0;
  std::optional<double> prewarning;
};
AnalogValues analog_values(const model::AnalogParams& a, double resolution);

// The value of a cause's input tag in the field: tripped or healthy.
model::TagValue cause_tag_value(const model::Cause& c, const model::CauseTag& t, bool tripped, double resolution);
// "19.9 %", "0 (de-energized)".
std::string tag_value_words(const model::Cause& c, const model::CauseTag& t, const model::TagValue& v,
                            double resolution);

// The observables a technician sees (the table of docs/testgen.md): output
// tags and the Viewer's status indications the configuration makes possible.
std::vector<model::Observable> technician_observables(const model::Matrix& m);

// "XV_221A closed (de-energized)", "cause 1 BSL201_FLAME_FAIL: trip requested on the Viewer".
std::string observation_words(const model::Matrix& m, const model::Observable& o, int value);

// The parts of a Viewer indication: "cause 1 BSL201_FLAME_FAIL", "Trip requested".
std::string viewer_element(const model::Matrix& m, const model::Observable& o);
std::string viewer_field(const model::Observable& o);

std::string cause_name(const model::Matrix& m, int id);   // "cause 1 BSL201_FLAME_FAIL"
std::string effect_name(const model::Matrix& m, int id);  // "effect 1 MFT_MAIN_GAS"
std::string seconds_text(std::uint64_t ms);               // "2.5 s", "1.5 min"

}  // namespace cemv::testgen::detail
