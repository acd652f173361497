// The matrix as a transition system (docs/encoding.md): the second,
// independent implementation of docs/semantics.md. Shares only the data model,
// the input/observable vocabulary and the evaluation order with the runtime.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <z3++.h>

#include "encoder/transition_system.hpp"
#include "model/graph.hpp"
#include "model/vocabulary.hpp"
#include "model/matrix.hpp"

namespace cemv::encoder {

// One per-cycle Boolean input standing for "the operator issues this command in
// this cycle" (docs/encoding.md, "Operator commands"). `value` is the value
// input of simulate_tag (Float32 for analog inputs, Bool otherwise).
struct CommandInput {
  model::CommandOp op = model::CommandOp::AckCause;
  int cause = 0;
  int effect = 0;
  int tag = 0;          // SoftBypassTag: 1-3
  int group = 0;
  bool on = true;       // soft bypass commands: the on- and the off-variant are separate inputs
  std::string tag_name; // SimulateTag / StopSimulation (empty: stop every simulation)
  z3::expr var;
  std::optional<z3::expr> value;

  // The concrete command this input stands for (value 0: the value input's
  // value is the trace's, not the encoding's).
  model::Command command() const;
};

struct Encoding {
  explicit Encoding(z3::context& ctx) : ts(ctx) {}
  TransitionSystem ts;
  model::InputTable inputs;
  // Per InputTable index: the value input (Bool, or Float32 for analog tags)
  // and the bad-quality input; absent when the cone of influence does not read
  // the tag.
  std::vector<std::optional<z3::expr>> tag_value;
  std::vector<std::optional<z3::expr>> tag_bad;
  std::vector<CommandInput> commands;
  // The encoded causes and effects (the cone of influence), evaluation order.
  std::vector<model::Node> nodes;
  // The observables of the encoded nodes, in model::observables order; each is a
  // named term of ts with the observable's key as its name.
  std::vector<model::Observable> observables;

  // The command input a concrete command maps to; nullptr when the command has
  // no effect in this encoding (target outside the cone, or never accepted).
  const CommandInput* find_command(const model::Command& c) const;

  // The matrix's fixed command order (model::CommandOrder); the command
  // inputs above were created in it.
  model::CommandOrder order;

  // EncodeOptions::guard_cells: each guarded cell's activation literal, a
  // free Boolean constant (neither state nor input, the same in every
  // cycle), by the cell's support key ("intersection[3,2]",
  // "cause[1].bypass_tag"; checker/support.hpp). Empty otherwise.
  std::vector<std::pair<std::string, z3::expr>> guards;

  // The commands of one cycle as the encoding processes them: the model's
  // canonical order (a set, repeats keep the last one's value) without the
  // commands the encoding has no input for (always refused, or outside the
  // cone). The runtime, given this list, must behave exactly as the encoding.
  std::vector<model::Command> canonical_commands(const std::vector<model::Command>& cmds) const;
};

struct EncodeOptions {
  // Each cell the support of a proof may leave out (docs/checker.md,
  // "Support") guarded by an activation literal (Encoding::guards): with the
  // literal true the cell acts as encoded, with it false the system is that
  // of the matrix without the cell. Guarded: the intersections outside XooN
  // groups (deleting a member invalidates the matrix), the bypass and
  // inhibit tags of causes, the bypass and reset tags of effects. An unsat
  // core over the literals names the cells a proof used (JKind's
  // activation literals for inductive validity cores).
  bool guard_cells = false;
};

// Builds the transition system of a validated matrix. `roots`: the causes and
// effects whose cone of influence (DependencyGraph::feeders_of) to encode;
// empty = every processed cause and effect.
std::unique_ptr<Encoding> encode(z3::context& ctx, const model::Matrix& m,
                                 const std::vector<model::Node>& roots = {}, const EncodeOptions& options = {});

}  // namespace cemv::encoder
