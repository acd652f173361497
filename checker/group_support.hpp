// The support's core query for the proofs of one cone group (docs/checker.md,
// "Support"): one encoding of the group's cone with each removable cell
// behind an activation literal (checker/cone_group.hpp, encode_group), one
// reduction and one context for every proof the group's members found,
// instead of one of each per proof. Each proof's obligations are asked with
// its own fresh solver there, the literals of its candidates assumed and
// every other guard held TRUE; the cells of the unsat cores are the support,
// which each member's checker re-checks on the matrix without the other
// cells (checker/property_support.cpp), as a support found alone is.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/cone_group.hpp"
#include "checker/prover.hpp"

namespace cemv::checker {

// What a proof's unsat core over the guarded cells says: the candidates a
// literal guards, and those of them the core uses. Any candidate outside
// `guarded` stays in the support.
struct SupportCore {
  std::set<std::string> guarded, used;
};

// One proof of the group whose support is asked.
struct SupportQuestion {
  std::size_t member = 0;           // index into the group's members
  const ProverResult* proof = nullptr;
  std::set<std::string> keys;       // its candidates (support.hpp, candidate_deletions)
};

// One answer per question, in order: nullopt where no core was found on the
// group's encoding (an obligation not unsat within the budget, an invariant
// that names what the group's encoding does not have, a member whose
// assumptions are not the group's); its checker then asks on its own
// encoding.
std::vector<std::optional<SupportCore>> group_support_cores(const model::Matrix& m,
                                                           const std::vector<GroupMember>& members,
                                                           const std::vector<SupportQuestion>& questions,
                                                           const CheckOptions& options, const Limits& limits);

}  // namespace cemv::checker
