// The bounded-response property that states "the path responds within T
// cycles", in the property language (docs/properties.md), built as a tree
// (properties/build.hpp) for the checker to decide. docs/response-time.md
// explains each part.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "properties/ast.hpp"
#include "response/paths.hpp"

namespace cemv::response {

enum class Mode { Normal, Degraded };

// A property file ("cemv-response:NAME") with one property named `name`:
// whenever the trigger of `p` rises on a quiet cause and holds, the effect's
// outputs are in their active state within `cycles` cycles; no bypass,
// inhibit, override or maintenance operation on the path. Degraded: one input
// of a voted trigger cause in bad quality throughout, the others as the
// degraded voting needs them. `assumed`: terms the property assumes never
// hold (`assume not (...)`), proved elsewhere (member_lemmas).
properties::PropertyFile response_property(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                           const std::string& name,
                                           const std::vector<properties::Expr>& assumed = {});

// The trip requirement of `cemv defeats` (docs/defeats.md): the normal bound
// of `cycles` cycles with none of the assumptions above about maintenance,
// faults and the holders' overrides. The caller states which actions are
// excluded, as `excluded` terms assumed never to hold; an input in bad
// quality counts toward the demand (the process behind a failed transmitter
// is unobserved, and in the worst case beyond the limit).
properties::PropertyFile requirement_property(const model::Matrix& m, const Path& p, long long cycles,
                                              const std::string& name,
                                              const std::vector<properties::Expr>& excluded);
// The same as text, with the excluded terms given as text: for a caller
// that still states its terms as text (defeats/enumerate.cpp).
std::string requirement_property_text(const model::Matrix& m, const Path& p, long long cycles,
                                      const std::string& name, const std::vector<std::string>& excluded);

// The member lemmas of an XooN path's bound (docs/response-time.md,
// "Compositional proof"). For each trigger cause i that is not timed, with
// its on-delay of d_i <= `cycles` cycles (0 without one), and for each
// condition of i the property's demand may hold (its normal one; in degraded
// mode also its degraded one when it is voted), the term L: "the condition
// has held for `cycles` cycles since a fresh rise, and cause i has not been
// active for the last `cycles` - d_i of them". `file` holds one
// property per term, `<name>.c<i>` (and `<name>.c<i>.degraded`), stating
// that it never holds, under the assumptions on cause i alone (no bypass,
// inhibit or maintenance on it): fewer than the bound's property makes, so
// what such a property proves holds in every run the bound judges, and the
// bound may assume its term never holds. The bound's proof is then a short
// induction over the effect's own delays. Nullopt for a single-cause path,
// or when no member gives a term.
struct MemberLemmas {
  std::vector<std::string> names;  // the properties, one per term
  std::vector<properties::Expr> terms;
  std::vector<long long> delays;   // the on-delay d_i in cycles of each term's cause
  properties::PropertyFile file;
};
std::optional<MemberLemmas> member_lemmas(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                          const std::string& name);

}  // namespace cemv::response
