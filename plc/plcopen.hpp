// PLCopen TC6 XML 2.01 (namespace http://www.plcopen.org/xml/tc6_0201) with
// Structured Text bodies (docs/plc.md P.9): the POUs with their interface
// variable lists and initial values, each `body/ST` read by the ST parser with
// its lines and columns placed in the XML file, standard block instances as
// `<derived name="TON"/>`, and the interval of the task that runs the program
// as its scan time. Bodies in LD, FBD, SFC or IL, and every element the
// subset does not cover, are refused at their element.
#pragma once

#include <string>
#include <string_view>

#include "plc/ast.hpp"

namespace cemv::plc {

inline constexpr std::string_view kPlcopenNamespace = "http://www.plcopen.org/xml/tc6_0201";

// Throws formats::LoadError at the first problem.
Program parse_plcopen(std::string_view text, const std::string& file);

// The program as PLCopen XML that parse_plcopen reads back: its POUs, the
// comments as `documentation`, the bodies as ST (print.hpp) in CDATA, and a
// cyclic task of `scan_time_ms` running the first PROGRAM when it is set.
// Deterministic (no clock in the file header).
std::string write_plcopen(const Program& program);

}  // namespace cemv::plc
