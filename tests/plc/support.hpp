// Helpers of the PLC tests: a refusal's place and message.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "formats/diagnostics.hpp"
#include "plc/parser.hpp"
#include "plc/plcopen.hpp"

namespace cemv::plc::test {

// The one issue a refused text gives: `FILE:LINE:COL: error: ...`.
inline formats::LoadIssue refusal(const std::string& text, const std::string& file = "prog.st") {
  try {
    parse_program_text(text, file);
  } catch (const formats::LoadError& e) {
    EXPECT_EQ(e.issues().size(), 1u);
    return e.issues().at(0);
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

#define EXPECT_REFUSED(text, line_, column_, words)                                   \
  do {                                                                                \
    const ::cemv::formats::LoadIssue issue_ = ::cemv::plc::test::refusal(text);       \
    EXPECT_EQ(issue_.line, static_cast<std::size_t>(line_)) << issue_.message();      \
    EXPECT_EQ(issue_.column, static_cast<std::size_t>(column_)) << issue_.message();  \
    EXPECT_NE(issue_.what.find(words), std::string::npos) << issue_.message();        \
    EXPECT_EQ(issue_.file, "prog.st");                                                \
  } while (0)

// A PROGRAM around a body: declarations first, then the statements (line 3 on).
inline std::string program(const std::string& vars, const std::string& body) {
  return "PROGRAM Main\nVAR " + vars + " END_VAR\n" + body + "\nEND_PROGRAM\n";
}

}  // namespace cemv::plc::test
