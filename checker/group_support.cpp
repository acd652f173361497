#include "checker/group_support.hpp"

#include "checker/check/recheck.hpp"
#include "checker/context_pool.hpp"

namespace cemv::checker {

std::vector<std::optional<SupportCore>> group_support_cores(const model::Matrix& m,
                                                           const std::vector<GroupMember>& members,
                                                           const std::vector<SupportQuestion>& questions,
                                                           const CheckOptions& options, const Limits& limits) {
  std::vector<std::optional<SupportCore>> out(questions.size());
  if (questions.empty()) return out;
  PooledContext ctx;
  const GroupEncoding b = encode_group(ctx, m, members, options, /*guard_cells=*/true);
  for (std::size_t q = 0; q < questions.size(); ++q) {
    stop_if_interrupted(limits);
    const SupportQuestion& question = questions[q];
    if (!b.shared[question.member]) continue;
    SupportCore core;
    std::vector<z3::expr> literals, fixed;
    for (const auto& [key, literal] : b.enc->guards) {
      if (question.keys.count(key)) {
        literals.push_back(literal);
        core.guarded.insert(key);
      } else {
        fixed.push_back(literal);
      }
    }
    // The invariant names the problem it was found on: the group's reduced
    // one (a group proof), or the member's own reduction (a proof of its
    // portfolio), whose variables the group's unreduced encoding has.
    const SafetyProblem reduced{b.reduced->problem.ts, b.goods[question.member], b.reduced->problem.assumption};
    const SafetyProblem original{b.original->problem.ts, b.original_goods[question.member],
                                 b.original->problem.assumption};
    std::optional<std::vector<z3::expr>> used =
        check::proof_core(reduced, *question.proof, literals, fixed, options.budgets.support, limits);
    if (!used) used = check::proof_core(original, *question.proof, literals, fixed, options.budgets.support, limits);
    if (!used) continue;
    for (const auto& l : *used) core.used.insert(l.decl().name().str().substr(std::string("guard.").size()));
    out[q] = std::move(core);
  }
  return out;
}

}  // namespace cemv::checker
