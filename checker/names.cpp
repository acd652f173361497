#include "checker/names.hpp"

#include <array>
#include <utility>

namespace cemv::checker {

namespace {

constexpr std::array<std::pair<Method, const char*>, 11> kMethods{{
    {Method::None, ""},
    {Method::Bmc, "bmc"},
    {Method::KInduction, "k-induction"},
    {Method::KInductionPlain, "k-induction-plain"},
    {Method::InvariantsInduction, "invariants+induction"},
    {Method::Pdr, "pdr"},
    {Method::AcceleratedBmc, "accelerated-bmc"},
    {Method::RelationalInduction, "relational-induction"},
    {Method::DirectedRun, "directed run"},
    {Method::RandomRun, "random run"},
    {Method::Portfolio, "portfolio"},
}};

}  // namespace

const char* to_string(Method m) {
  for (const auto& [method, word] : kMethods)
    if (method == m) return word;
  return "";
}

std::string method_text(Method m, bool localized) {
  std::string s = to_string(m);
  return localized ? s + ", localized" : s;
}

std::optional<Method> method_from_string(std::string_view word) {
  for (const auto& [method, w] : kMethods)
    if (method != Method::None && word == w) return method;
  return std::nullopt;
}

const char* to_string(UnknownReason r) {
  switch (r) {
    case UnknownReason::None: return "";
    case UnknownReason::TimeLimit: return "time limit";
    case UnknownReason::WorkLimit: return "work limit";
    case UnknownReason::BoundReached: return "bound reached";
    case UnknownReason::MemoryLimit: return "memory limit";
    case UnknownReason::SolverGaveUp: return "solver gave up";
    case UnknownReason::NoDirectedRun: return "no directed run violates it";
    case UnknownReason::CannotRun: return "the evaluator cannot run this system";
  }
  return "";
}

}  // namespace cemv::checker
