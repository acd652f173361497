#include "checker/round_values.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "checker/concrete_judge.hpp"

namespace cemv::checker {

namespace {

// Rounder numbers near `v`, roundest first: for 0-3 decimals, the two
// neighbours at that many decimals, nearer first. `v` itself ends the list
// once a candidate equals it (nothing rounder than v at that precision).
std::vector<float> rounder_numbers(float v) {
  std::vector<float> out;
  if (!std::isfinite(v)) return out;
  for (int decimals = 0; decimals <= 3; ++decimals) {
    const double scale = std::pow(10.0, decimals);
    const double lo = std::floor(static_cast<double>(v) * scale) / scale;
    const double hi = std::ceil(static_cast<double>(v) * scale) / scale;
    const double near = std::fabs(lo - v) <= std::fabs(hi - v) ? lo : hi;
    const double far = near == lo ? hi : lo;
    for (double c : {near, far}) {
      const float f = static_cast<float>(c);
      if (f == v) return out;
      if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
    }
  }
  return out;
}

}  // namespace

Trace round_values(const SafetyProblem& problem, const Trace& cex) {
  Trace t = cex;
  try {
    ConcreteJudge judge(problem);
    if (!judge.violates(t)) return cex;
    const std::size_t n = t.cycles.size();
    for (std::size_t i = 0; i < t.input_names.size(); ++i) {
      for (std::size_t lo = 0; lo < n;) {
        const Value held = t.cycles[lo].inputs[i];
        std::size_t hi = lo + 1;
        while (hi < n && t.cycles[hi].inputs[i] == held) ++hi;
        if (held.is_float)
          for (float c : rounder_numbers(held.f)) {
            Trace trial = t;
            for (std::size_t k = lo; k < hi; ++k) trial.cycles[k].inputs[i].f = c;
            if (!judge.violates(trial)) continue;
            t = std::move(trial);
            break;
          }
        lo = hi;
      }
    }
    judge.record_states(t);
  } catch (const std::logic_error&) {
    return cex;  // an operator the evaluator does not interpret
  }
  return t;
}

}  // namespace cemv::checker
