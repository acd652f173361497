// Structural equality of property trees, source places aside: what a test
// needs to hold a generated property to the tree the parser makes of its
// printed text (properties/print.hpp: "the same AST up to source locations").
#pragma once

#include <cstring>
#include <string>

#include "properties/ast.hpp"

namespace cemv::testsupport {

// Empty when equal, else where the trees part.
inline std::string tree_difference(const properties::Expr& a, const properties::Expr& b, const std::string& at = "") {
  using K = properties::Expr::Kind;
  if (a.kind != b.kind || a.type != b.type) return at + ": kind or type";
  if (a.bool_value != b.bool_value || a.int_value != b.int_value ||
      std::memcmp(&a.float_value, &b.float_value, sizeof(float)) != 0)
    return at + ": constant";
  if (a.kind == K::Observable && a.observable.key != b.observable.key) return at + ": " + a.observable.key;
  if ((a.kind == K::InputValue || a.kind == K::InputBad) && a.input != b.input) return at + ": input";
  const auto &p = a.command, &q = b.command;
  if (a.kind == K::CommandIssued && (p.op != q.op || p.cause != q.cause || p.effect != q.effect || p.tag != q.tag ||
                                     p.group != q.group || p.on != q.on || p.tag_name != q.tag_name))
    return at + ": command";
  if (a.cmp != b.cmp || a.cycles != b.cycles) return at + ": comparison or cycles";
  if (a.args.size() != b.args.size()) return at + ": arity";
  for (std::size_t i = 0; i < a.args.size(); ++i)
    if (auto d = tree_difference(a.args[i], b.args[i], at + "/" + std::to_string(i)); !d.empty()) return d;
  return "";
}

inline std::string tree_difference(const properties::Property& a, const properties::Property& b) {
  if (a.name != b.name || a.kind != b.kind || a.description != b.description || a.within_cycles != b.within_cycles)
    return a.name + ": name, kind, description or bound";
  if (a.assumptions.size() != b.assumptions.size()) return a.name + ": assumptions";
  for (std::size_t i = 0; i < a.assumptions.size(); ++i)
    if (auto d = tree_difference(a.assumptions[i].expr, b.assumptions[i].expr, a.name + " assumption"); !d.empty())
      return d;
  if (a.kind == properties::PropertyKind::Response) {
    if (auto d = tree_difference(a.trigger, b.trigger, a.name + " trigger"); !d.empty()) return d;
    return tree_difference(a.response, b.response, a.name + " response");
  }
  return tree_difference(a.body, b.body, a.name);
}

inline std::string tree_difference(const properties::PropertyFile& a, const properties::PropertyFile& b) {
  if (a.assumptions.size() != b.assumptions.size() || a.properties.size() != b.properties.size())
    return "number of assumptions or properties";
  for (std::size_t i = 0; i < a.assumptions.size(); ++i)
    if (auto d = tree_difference(a.assumptions[i].expr, b.assumptions[i].expr, "file assumption"); !d.empty()) return d;
  for (std::size_t i = 0; i < a.properties.size(); ++i)
    if (auto d = tree_difference(a.properties[i], b.properties[i]); !d.empty()) return d;
  return "";
}

}  // namespace cemv::testsupport
