// A program as Structured Text: what parse_st reads back as the same program
// (without positions). export-st builds an AST and prints it here.
#pragma once

#include <string>

#include "plc/ast.hpp"

namespace cemv::plc {

std::string print_program(const Program& p);
std::string print_pou(const Pou& pou);
std::string print_expression(const Expr& e);
// One statement at `indent` spaces, ending in a newline.
std::string print_statement(const Statement& s, int indent = 0);

}  // namespace cemv::plc
