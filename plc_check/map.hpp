// The map between a matrix and a program, completed (docs/plc.md "Map and
// relations"): every matrix input tag, output tag and operator command the
// matrix accepts is bound to a program variable or declared (held at a value,
// unused), every program input is accounted for, the scan time is fixed, and
// every assumption is written out for the reports. What the given map leaves
// out is found by name (letter case, `-` and `_` ignored).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/plc_map.hpp"
#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::plc_check {

enum class VarType { Bool, Int, Real, Time, Other };
enum class VarKind { Input, Output, InOut, Local };

// A variable of the program's POU as the map needs it (plc_check's view of
// the program's interface, filled from the program's AST).
struct ProgramVariable {
  std::string name;
  VarKind kind = VarKind::Local;
  VarType type = VarType::Bool;
};

struct ProgramInterface {
  std::string file;                       // where messages about the program point
  std::string pou;                        // the POU checked
  std::vector<ProgramVariable> variables;
  std::optional<std::uint32_t> task_ms;   // the task interval a PLCopen file states
};

// One operator command the matrix accepts that can change an output tag
// (O.1-O.8 as configured); clear_first_out and clear_alarms change status
// only and have none. stop_simulation has none either while every
// simulate_tag is unused, which cemv-plc-map/1 requires.
struct CommandSlot {
  model::Command command;
  std::string label;         // "soft_bypass_cause cause 1 LT100_HH on"
  std::string default_name;  // the variable a program names for it: LT100_HH_SOFT_BYPASS_ON, LT100_HH_TAG2_SOFT_BYPASS_OFF
};
std::vector<CommandSlot> command_slots(const model::Matrix& m);

// Letter case, `-` and `_` dropped: the key by which names match by default.
std::string name_key(std::string_view name);

struct ResolvedMap {
  formats::PlcMap map;                    // complete, in the matrix's order
  std::uint32_t scan_ms = 0;
  std::vector<std::string> assumptions;   // printed in every report
};

// Completes `given` (nullptr: nothing given) against the matrix and the
// program. Throws formats::LoadError listing everything left unaccounted for
// or bound wrongly (placed in `map_source` when a map was given, else in the
// program's file).
ResolvedMap resolve_map(const model::Matrix& m, const ProgramInterface& program, const formats::PlcMap* given,
                        const std::string& map_source);

}  // namespace cemv::plc_check
