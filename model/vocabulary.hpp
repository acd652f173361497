// The vocabulary shared by everything that executes or encodes a matrix: which
// input tags a matrix reads, what one scan cycle's inputs and operator commands
// look like, and the names of the status fields a scenario can expect.
// Data only: what these mean is docs/semantics.md, implemented twice (runtime/,
// encoder/).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "model/matrix.hpp"
#include "model/node.hpp"

namespace cemv::model {

// ---- Tag names ------------------------------------------------------------

// Tag names match case-insensitively (6.1.4): this is the key to compare them by.
std::string tag_key(std::string_view name);

// An internal reference (6.1.3): Cause[x], Effect[x] or Effect[x][y].
struct InternalRef {
  enum class Kind { Cause, Effect, EffectTag } kind = Kind::Cause;
  int id = 0;
  int tag = 0;  // y of Effect[x][y], 1-based; 0 otherwise
};
// Parses an internal reference; nullopt when the name is an ordinary tag.
std::optional<InternalRef> parse_internal_ref(std::string_view name);

// ---- Input tags -------------------------------------------------------------

enum class TagKind { Bool, Analog };

// Why the matrix reads a tag; one tag may serve several roles (then the first
// role in this order names its kind).
enum class TagRole {
  CauseInput,        // a cause's input tag (discrete or analog)
  CauseBypass,
  CauseInhibit,
  EffectBypass,
  EffectReset,
  ProcessValue,      // process_data.tag
  Mask,              // process_data.mask_tag
  SecureWriteEnable,
  GroupDeactivationEnable,
  GroupDeactivationSet,
};

struct InputTag {
  std::string name;      // as first written in the matrix
  TagKind kind = TagKind::Bool;
  std::vector<TagRole> roles;
};

// Every external input of a matrix (internal references excluded), in a fixed
// order: the order of first appearance walking the matrix in its canonical order
// (matrix-level tags, then causes by id, then effects by id). Input frames are
// indexed by this order.
class InputTable {
 public:
  explicit InputTable(const Matrix& m);
  InputTable() = default;
  const std::vector<InputTag>& tags() const { return tags_; }
  std::size_t size() const { return tags_.size(); }
  // Index of a tag by name (case-insensitive); nullopt when the matrix does not read it.
  std::optional<std::size_t> find(std::string_view name) const;

 private:
  std::vector<InputTag> tags_;
  std::vector<std::pair<std::string, std::size_t>> by_key_;  // sorted by key
};

// The value of one input tag in one cycle. Boolean tags use 0/1.
struct TagValue {
  float value = 0.0f;
  bool bad_quality = false;
};

// ---- Operator commands (10.7) ---------------------------------------------

enum class CommandOp {
  AckCause,            // cause
  ResetEffect,         // effect
  OverrideEffect,      // effect
  StopOverride,        // effect
  SoftBypassCause,     // cause, on
  SoftBypassTag,       // cause, tag (1-3), on
  SoftBypassEffect,    // effect, on
  SimulateTag,         // tag_name, value
  StopSimulation,      // tag_name (empty: every simulation)
  ClearFirstOut,       // group
  ClearAlarms,         // cause or effect
};
const char* to_string(CommandOp);
std::optional<CommandOp> command_op_from_string(std::string_view);

struct Command {
  CommandOp op = CommandOp::AckCause;
  int cause = 0;       // 0 = not given
  int effect = 0;
  int tag = 0;         // 1-based tag index for SoftBypassTag
  int group = 0;
  bool on = true;
  std::string tag_name;  // SimulateTag / StopSimulation
  float value = 0.0f;
};

// Everything one scan cycle consumes: a value per input tag (indexed by the
// InputTable) and the operator commands issued in that cycle.
struct CycleInput {
  std::vector<TagValue> tags;
  std::vector<Command> commands;
};

// ---- The fixed command order (M.1, docs/encoding.md "Operator commands") ----

// The one order in which a cycle's commands are processed as a set. The
// encoder creates its command inputs in this order, so the runtime, given a
// cycle's commands in this order, computes exactly what the encoding computes:
// every replay that compares the two (the differential test, the checker's
// counterexamples and the scenarios written from them) orders commands here.
//  1. simulate_tag, by simulatable tag (simulatable_tags());
//  2. stop_simulation by simulatable tag, then for every tag (empty name);
//  3. soft_bypass_cause by cause: on, then off;
//  4. soft_bypass_tag by cause and tag position: on, then off;
//  5. soft_bypass_effect by effect: on, then off;
//  6. the commands without interplay: clear_first_out by group, clear_alarms
//     of each cause, then of each effect, ack_cause by cause, then per effect
//     reset_effect, override_effect, stop_override.
// Causes and effects go in the matrix's order (by id), processed ones only
// (M.4). The order is by target, not by configuration: whether the matrix can
// ever accept a command (O.1-O.10) is semantics, decided by each implementation.
class CommandOrder {
 public:
  CommandOrder() = default;
  explicit CommandOrder(const Matrix& m);

  // The tags O.8 lets an operator simulate, in order: external cause input
  // tags in InputTable order (spelt as there), then output tags of processed
  // effects by effect and position (spelt as the effect writes them).
  const std::vector<std::string>& simulatable_tags() const { return simulatable_; }

  // The commands of one cycle as a set in this order. A clear_alarms naming a
  // cause and an effect counts as the two commands (O.10); repeats of one
  // command (same op and target, same on/off) keep the last one, with its
  // value and spelling. A command naming nothing of the matrix (an unknown
  // element, tag position, tag or group), which every cycle refuses alike,
  // goes after all others, ordered by op and target.
  std::vector<Command> canonical(const std::vector<Command>& cmds) const;

  // The position of a command in the order; nullopt for one naming nothing of
  // the matrix (and for clear_alarms naming both or neither).
  std::optional<std::size_t> rank(const Command& c) const;

 private:
  using Key = std::tuple<int, int, int, int, int, bool, std::string>;
  static Key key_of(const Command& c);
  void add(const Command& c);
  // The order's groups, in the order they are added (docs/semantics.md, M.1).
  void add_simulation(const Matrix& m, const std::vector<const Effect*>& effects);           // O.8
  void add_soft_bypasses(const std::vector<const Cause*>& causes, const std::vector<const Effect*>& effects);  // O.7
  void add_alarms_and_acks(const std::vector<const Cause*>& causes, const std::vector<const Effect*>& effects);  // O.9, O.10, O.4
  void add_resets_and_overrides(const std::vector<const Effect*>& effects);                  // O.2, O.3

  std::vector<std::string> simulatable_;
  std::map<Key, std::size_t> rank_;
};

// ---- Default inputs ---------------------------------------------------------

// The value of one input tag before any scenario sets it (docs/scenario.md, "Defaults"):
// cause inputs at their non-tripped value (discrete DTT TRUE, ETT FALSE; analog
// high limit - hysteresis - 1.0, low limit + hysteresis + 1.0, computed in double
// and rounded once to float), every other Boolean tag FALSE, good quality. A tag
// read by several causes takes the value of the first cause (by id) that reads it.
TagValue default_tag_value(const Matrix& m, const InputTag& tag);
// Every input at its default, no commands; indexed by InputTable(m).
CycleInput default_cycle_input(const Matrix& m);

// ---- Status fields (the scenario format's expect keys) ----------------------

// Fields of `cause[ID].FIELD` and `effect[ID].FIELD`, in a fixed order. Both the
// runtime and the encoder report exactly these, under these names.
enum class FieldType { Bool, Int, Voting };
struct FieldInfo { const char* name; FieldType type; };
const std::vector<FieldInfo>& cause_fields();
const std::vector<FieldInfo>& effect_fields();

// Resulting voting logic of a cause, as the scenario spells it.
enum class Voting { OneOoOne, OneOoTwo, TwoOoTwo, OneOoThree, TwoOoThree, ThreeOoThree, Bypass };
const char* to_string(Voting);
std::optional<Voting> voting_from_string(std::string_view);

// Every observable value of a matrix, in a fixed order: for each processed
// cause by id its cause_fields(), for each processed effect by id its
// effect_fields() then `effect[ID].tag[k]` for k = 1..tags (the output value,
// 0/1). The runtime and the encoder each produce a value for every key, which
// is what the differential test compares cycle by cycle.
struct Observable {
  std::string key;      // "cause[3].active", "effect[2].tag[1]"
  FieldType type = FieldType::Bool;
  Node::Kind kind = Node::Kind::Cause;
  int id = 0;
  std::string field;    // "active", or "tag" for output values
  int tag = 0;          // k of tag[k]
};
std::vector<Observable> observables(const Matrix& m);

// The one spelling of an observable's key: "cause[3].active" (a status field of
// element `n`), "effect[2].tag[1]" (field "tag", output k = tag >= 1).
std::string observable_key(const Node& n, std::string_view field, int tag = 0);

}  // namespace cemv::model
