// The actions of `cemv defeats` (docs/defeats.md, "Actions"): what an operator
// or a fault may do in a path's cone of influence that cemv response assumes
// away. Each is excluded from a question by a term assumed never to hold.
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "response/paths.hpp"

namespace cemv::defeats {

enum class ActionKind {
  SoftBypassCause,   // O.5: soft_bypass_cause of a cause whose soft bypass is allowed
  SoftBypassTag,     // O.6: soft_bypass_tag of a cause tag whose soft bypass is allowed
  SoftBypassEffect,  // O.7
  CauseBypassTag,    // C.8: an external bypass tag TRUE
  CauseInhibitTag,   // C.8: an external inhibit tag TRUE
  EffectBypassTag,   // E.1: an external bypass tag TRUE
  Override,          // E.3: an effect with an override block and a V or R cell
  MaskTag,           // E.8: an external mask tag TRUE
  SimulateInput,     // O.8: an external cause input tag simulated
  SimulateOutput,    // O.8: an output tag of an effect simulated
  BadQuality,        // C.3: an external cause input tag in bad quality (a fault)
};

// The word of each kind, as cemv-defeats/1 writes it.
const char* to_string(ActionKind k);

struct Action {
  ActionKind kind = ActionKind::BadQuality;
  int cause = 0;      // the cause (soft bypass, tag soft bypass, bypass and inhibit tags), else 0
  int effect = 0;     // the effect (effect soft bypass, bypass tag, override, mask, output simulation), else 0
  int tag_index = 0;  // SoftBypassTag: 1-3
  std::string tag;    // the tag named (bypass, inhibit, mask, simulated, bad), "" for a command on an element

  // A stable, readable key: "soft_bypass_cause[1]", "bad_quality[LT_100A]".
  std::string key() const;
  // The term whose never holding excludes the action (property language).
  std::string excluded_term() const;
  // For people: "soft bypass of cause 1 LT100_HH".
  std::string description(const model::Matrix& m) const;
  auto operator<=>(const Action&) const = default;
};

// Every action the configuration allows in the cone of influence of the
// path's effect (the causes and effects whose value reaches it), one per tag
// where several elements share it, in a fixed order: by element (causes by
// id, then effects), and within one as listed in ActionKind, tag by tag. The
// actions of one element are neighbours, so that the divide and conquer of
// the enumeration keeps them together.
std::vector<Action> actions_of(const model::Matrix& m, const response::Path& p);

// Whether the action is an operation whose purpose is to take one of the
// path's own elements (its trigger causes, its effect) out of service: a
// bypass (hard or soft, of the cause or of one of its tags) or inhibit of a
// trigger cause; a bypass, override or mask of the effect; a simulation of a
// trigger cause's input or the effect's output. Bad quality never is, nor an
// operation on a relay or an intermediate effect of a chain.
bool declared_for(const model::Matrix& m, const response::Path& p, const Action& a);

}  // namespace cemv::defeats
