// The map between a matrix and a PLC program, `cemv-plc-map/1` (docs/plc.md
// "Map and relations"): which program variable carries each matrix input tag
// (and its bad quality), each output tag and each operator command, which
// commands are assumed never to be issued, which program inputs are held
// constant, and the scan time. Data, reader and writer only: completing a map
// against a matrix and a program is plc_check/'s work.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/vocabulary.hpp"

namespace cemv::formats {

inline constexpr const char* kPlcMapFormat = "cemv-plc-map/1";

// One matrix input tag: the program variable that reads it, or the constant
// value the tag is held at (an assumption printed in every report). A cause
// input may name the BOOL variable that reads its bad quality; without one
// the tag is assumed to be of good quality.
struct PlcInputBinding {
  std::string tag;
  std::string variable;           // empty: held at `value`
  std::optional<double> value;    // only without a variable
  std::string bad_quality;        // empty: good quality assumed
  bool good_quality = false;      // `"bad_quality": false` written: good quality declared
};

// One output tag of a processed effect and the program variable that writes
// it. `effect` is needed only when several effects write one tag name.
struct PlcOutputBinding {
  std::string tag;
  int effect = 0;                 // 0: the tag name alone decides
  std::string variable;
};

// Operator commands (10.7) the program does not read from a tag: one entry
// names one command (every field given) or, declared unused, a set of them
// (a field left out matches every value). A command mapped to a variable is
// issued in exactly the scans where that BOOL variable is TRUE.
struct PlcCommandBinding {
  model::CommandOp op = model::CommandOp::AckCause;
  int cause = 0;                  // 0: any
  int effect = 0;                 // 0: any
  int tag = 0;                    // soft_bypass_tag: 1-based position; 0: any
  std::string tag_name;           // simulate_tag: empty = any
  std::optional<bool> on;         // soft bypasses: nullopt = on and off
  std::string variable;           // empty: unused (assumed never issued)
};

// A program input that has no matrix counterpart, held at a value.
struct PlcProgramInput {
  std::string variable;
  double value = 0.0;
};

struct PlcMap {
  std::string pou;                          // empty: the program's only PROGRAM
  std::optional<std::uint32_t> scan_ms;     // nullopt: the program's task interval, else the matrix's cycle
  std::vector<PlcInputBinding> inputs;
  std::vector<PlcOutputBinding> outputs;
  std::vector<PlcCommandBinding> commands;
  std::vector<PlcProgramInput> program_inputs;
};

// Reads a map (guarded JSON, every problem placed at FILE:LINE:COL with its
// JSON path). Throws LoadError.
PlcMap parse_plc_map(std::string_view json_text, const std::string& source_name);

// The map as JSON, keys in a fixed order, entries in the order given.
// Deterministic; parse_plc_map gives the same map back.
std::string plc_map_json(const PlcMap& map);

}  // namespace cemv::formats
