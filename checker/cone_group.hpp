// Properties that share a cone of influence (and their assumptions) are
// decided on one encoding (docs/checker.md, "Cone groups"): one transition
// system with every member's monitor compiled into it, one reduction, one
// set of seeded random runs, one invariant search, one unrolling. What the
// shared questions answer is checked like every answer (a proof re-checked
// in a fresh context built the same way, a run replayed by the member's own
// checker on the runtime and on the member's own encoding); what they leave
// open goes to the member's own portfolio (checker/property_checker.hpp).
//
// The group's steps, cheap first:
//   runs     runs of the cone on the reference runtime, judged for every
//            member: a cover's witness, a violation, a witness that a
//            member's antecedent can hold (its vacuity question). First the
//            causes each member names tripped (alone, then together), then
//            seeded random runs (checker/random_runs.hpp);
//   proofs   k-induction with k <= 1 for every member (engines/multi.hpp),
//            strengthened by the encoder's lemmas for the members whose
//            monitor counts no cycles;
//   reach    shallow BMC for the covers still open, and on a small cone for
//            the antecedents too (before the runs there).
// Every step has a budget of work or of simulated cycles, and the members
// are taken in a fixed order, so the answers do not depend on the machine or
// on the number of workers.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "checker/prover.hpp"
#include "checker/random_runs.hpp"
#include "checker/shrink.hpp"
#include "encoder/encode.hpp"
#include "properties/ast.hpp"

namespace cemv::checker {

struct GroupMember {
  const properties::PropertyFile* file = nullptr;
  const properties::Property* property = nullptr;
};

// What the group knows of its cone, for each member's own checker.
struct ConeFacts {
  bool has_antecedent = false;
  PreferredValue preferred;   // the plant at rest
  RunSpace space;             // the cone's inputs and commands, for random runs
};

// What the group's shared questions answered for one member.
struct EarlyAnswer {
  ConeFacts facts;
  std::optional<ProverResult> proof;    // Proved, already re-checked
  std::vector<model::CycleInput> run;   // a cover's witness or a violation, to replay
  Method run_method = Method::None;
  bool vacuity_witnessed = false;       // a run in which the assumptions and the antecedent held
  bool runs_tried = false;              // the group's random runs were judged for it
};

// The group's one encoding: its cone with every member's monitor compiled
// in, in member order (the same names in every context, so an invariant's
// text reads in each), and one reduction that keeps every member's `good`
// and antecedent.
struct GroupEncoding {
  std::shared_ptr<encoder::Encoding> enc;
  std::optional<OwnedProblem> original;  // the group's encoding, the shared assumption
  std::optional<OwnedProblem> reduced;
  std::vector<z3::expr> goods;                       // reduced, one per member
  std::vector<z3::expr> original_goods;              // unreduced, one per member
  std::vector<std::optional<z3::expr>> antecedents;  // reduced, one per member
  std::vector<bool> shared;                          // the member's assumption is the group's
};
// `guard_cells`: each removable cell behind an activation literal
// (encoder::EncodeOptions::guard_cells), for the support's core query.
// `reduce` false: no reduction (`reduced` and `goods` empty, `antecedents`
// the unreduced terms), for a caller that needs only what the encoding
// says of the cone.
GroupEncoding encode_group(z3::context& ctx, const model::Matrix& m, const std::vector<GroupMember>& members,
                           const CheckOptions& options, bool guard_cells = false, bool reduce = true);

class ConeGroup {
 public:
  ConeGroup(const model::Matrix& m, std::vector<GroupMember> members, const CheckOptions& options);
  // One answer per member, in member order.
  std::vector<EarlyAnswer> decide(const Limits& limits);

 private:
  using Built = GroupEncoding;
  void random_runs(std::vector<EarlyAnswer>& out, const Limits& limits) const;
  void prove(Built& b, std::vector<EarlyAnswer>& out, const Limits& limits) const;
  // `antecedents`: also the witnesses that proved members' antecedents can
  // hold (not only the covers').
  void reach(Built& b, std::vector<EarlyAnswer>& out, const Limits& limits, bool antecedents) const;
  void recheck(const Built& b, std::vector<EarlyAnswer>& out, const Limits& limits) const;

  const model::Matrix& m_;
  std::vector<GroupMember> members_;
  const CheckOptions& options_;
  std::vector<std::vector<model::Node>> roots_of_;  // each member's
};

// The members of `jobs` (file, property) in groups: the same cone of
// influence and the same assumptions, in the order of each group's first
// member. Returns the indices into `jobs`.
std::vector<std::vector<std::size_t>> cone_groups(const model::Matrix& m, const std::vector<GroupMember>& jobs);

}  // namespace cemv::checker
