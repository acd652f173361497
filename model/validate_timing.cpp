#include "model/validate_timing.hpp"

#include <cstdint>
#include <set>

namespace cemv::model::detail {

std::vector<TimingFinding> timing_findings(const Matrix& m) {
  std::vector<TimingFinding> out;
  auto at_matrix = [&](const char* rule, std::string message) {
    out.push_back({rule, 0, 0, "matrix", std::move(message)});
  };
  // HIMatrix 3.2.3: the watchdog time bounds one cycle, so it cannot be
  // shorter than the cycle the matrix runs in.
  if (m.watchdog_ms && m.cycle_ms > 0 && *m.watchdog_ms < m.cycle_ms)
    at_matrix("E-WATCHDOG-CYCLE", "watchdog_ms " + std::to_string(*m.watchdog_ms) +
                                      " is shorter than cycle_ms " + std::to_string(m.cycle_ms) +
                                      ": every cycle would trip the watchdog");
  std::set<int> members;
  for (const auto& c : m.causes)
    if (c.function != CauseFunction::Comment) members.insert(c.sif.begin(), c.sif.end());
  for (const auto& e : m.effects)
    if (e.function != EffectFunction::Comment) members.insert(e.sif.begin(), e.sif.end());
  for (const auto& [group, name] : m.sif_groups) {
    auto pst = m.process_safety_time_ms.find(group);
    const std::string label = "SIF group " + std::to_string(group) + " '" + name + "'";
    if (pst == m.process_safety_time_ms.end()) {
      if (members.count(group))
        at_matrix("W-SIF-NO-PST", label + " has members but declares no process_safety_time_ms: "
                                          "its response time cannot be judged");
      continue;
    }
    if (!members.count(group))
      at_matrix("W-SIF-PST-NO-MEMBERS",
                label + " declares a process safety time but no processed cause or effect belongs to it");
    // HIMatrix 3.2.3 / 3.2.6: the controller alone takes up to twice the
    // watchdog time (twice the cycle without one); a process safety time not
    // longer than that leaves nothing for sensor, logic and actuator.
    const std::uint64_t share = 2ull * (m.watchdog_ms ? *m.watchdog_ms : m.cycle_ms);
    if (pst->second <= share)
      at_matrix("W-PST-CONTROLLER",
                label + ": process_safety_time_ms " + std::to_string(pst->second) +
                    " is not longer than the controller's share of " + std::to_string(share) + " ms (2 x " +
                    (m.watchdog_ms ? "watchdog_ms" : "cycle_ms") + ")");
  }
  return out;
}

}  // namespace cemv::model::detail
