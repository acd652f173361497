// Small constructors of plc/ AST nodes for the generator: the program is built
// as a tree and printed by plc/print.hpp, never assembled as text. Boolean
// helpers fold the constants TRUE and FALSE away so that an option the matrix
// does not use leaves no trace in the program.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "plc/ast.hpp"

namespace cemv::plc_export::st {

plc::Expr var(const std::string& name, plc::Type type = plc::Type::Bool);
plc::Expr member(const std::string& instance, plc::Pin pin, plc::Type type = plc::Type::Bool);
plc::Expr boolean(bool value);
plc::Expr real(float value);
plc::Expr integer(std::int64_t value, plc::Type type = plc::Type::Dint);
plc::Expr time_ms(std::int64_t ms);

bool is_true(const plc::Expr& e);
bool is_false(const plc::Expr& e);

plc::Expr not_(plc::Expr a);
plc::Expr and_(plc::Expr a, plc::Expr b);
plc::Expr or_(plc::Expr a, plc::Expr b);
plc::Expr all(std::vector<plc::Expr> terms);  // TRUE when empty
plc::Expr any(std::vector<plc::Expr> terms);  // FALSE when empty
plc::Expr binary(plc::BinaryOp op, plc::Expr a, plc::Expr b, plc::Type result);
plc::Expr sel(plc::Expr g, plc::Expr in0, plc::Expr in1, plc::Type type);

plc::Statement assign(const std::string& target, plc::Expr value, std::string comment = {});
plc::Statement if_(plc::Expr condition, std::vector<plc::Statement> then_body, std::string comment = {});
plc::Statement if_else(plc::Expr condition, std::vector<plc::Statement> then_body,
                       std::vector<plc::Statement> else_body, std::string comment = {});
// An IF with ELSIF branches (conditions and bodies in order) and an ELSE.
plc::Statement if_chain(std::vector<plc::Branch> branches, std::vector<plc::Statement> else_body,
                        std::string comment = {});
plc::Statement call(const std::string& instance, std::vector<std::pair<plc::Pin, plc::Expr>> inputs,
                    std::string comment = {});

plc::Variable variable(const std::string& name, plc::Section section, plc::Type type, std::string comment = {});
plc::Variable block(const std::string& name, plc::StandardBlock b, std::string comment = {});

}  // namespace cemv::plc_export::st
