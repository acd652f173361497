#include "checker/prover.hpp"

#include <cstdio>

namespace cemv::checker {

std::string ProverResult::reason_text() const {
  std::string s = to_string(reason);
  return detail.empty() ? s : s + ": " + detail;
}

std::string Value::text() const {
  if (!is_float) return std::to_string(i);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(f));
  return buf;
}

namespace {
std::size_t index_of(const std::vector<std::string>& names, const std::string& name) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  throw std::out_of_range("no variable " + name + " in the trace");
}
}  // namespace

Value Trace::input(std::size_t cycle, const std::string& name) const {
  return cycles.at(cycle).inputs.at(index_of(input_names, name));
}

Value Trace::state(std::size_t cycle, const std::string& name) const {
  return cycles.at(cycle).state.at(index_of(state_names, name));
}

std::string Invariant::text() const {
  std::string out;
  for (const auto& c : clauses) out += c + "\n";
  return out;
}

std::string Invariant::smtlib() const {
  if (clauses.empty()) return "true";
  if (clauses.size() == 1) return clauses[0];
  std::string out = "(and";
  for (const auto& c : clauses) out += " " + c;
  return out + ")";
}

std::string to_string(Verdict v) {
  switch (v) {
    case Verdict::Proved: return "proved";
    case Verdict::Falsified: return "falsified";
    case Verdict::Unknown: return "unknown";
  }
  return "unknown";
}

}  // namespace cemv::checker
