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

}  // namespace cemv::plc
