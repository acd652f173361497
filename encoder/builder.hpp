// Inside encode() (encode.cpp, encode_commands.cpp, encode_cause.cpp,
// encode_effect.cpp): the parts of the encoding of one scan cycle, in the
// order M.1 makes them. Reads: the matrix level and what an element reads;
// CommandEncoder: phase 2, the operator commands; CauseEncoder and
// EffectEncoder: phase 3, one element each, and phase 4, first out; Builder
// puts them together over the cone. Not a public header: nothing outside
// encoder/ includes it.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "encoder/terms.hpp"

namespace cemv::encoder::detail {

// A simulatable tag (O.8): its simulation state after this cycle's commands.
struct Simulation {
  std::string name;
  bool analog = false;
  bool output = false;
  bool allowed = true;  // no element that reads or writes it forbids simulating it
  expr on;
  expr value;
  expr on_prev;    // state variable
  expr value_prev; // state variable
};

// Phase 1 of M.1 (the first cycle, group deactivation, secure write), the
// inputs of the tags as they are first read, and internal references (I.3,
// I.4): the current value of an element evaluated before its reader, else
// the previous cycle's, a state variable given its next value at the end.
class Reads : public Terms {
 public:
  Reads(z3::context& ctx, const model::Matrix& m, Encoding& enc, bool guard_cells)
      : Terms(ctx, enc, guard_cells), m_(m), graph_(m), first_(ctx), cmd_ok_(ctx), gd_(ctx) {}

  const model::DependencyGraph& graph() const { return graph_; }
  void build_matrix_level();
  expr first() const { return first_; }    // cycle 1 (T.3)
  expr cmd_ok() const { return cmd_ok_; }  // M.3: commands accepted in this cycle
  expr gd() const { return gd_; }          // M.2: group deactivation in this cycle

  // The raw input of a tag (I.1); created on first use.
  expr raw_value(std::size_t index);
  expr raw_bad(std::size_t index);
  // A Boolean read of a tag slot by `reader` (E.1, C.8, M.2): an internal
  // reference (I.3, I.4) or the raw input value; nullopt reader = matrix level.
  expr bool_read(const std::string& name, const std::optional<Node>& reader);
  expr ref_value(const model::InternalRef& r, const std::optional<Node>& reader);
  // T.4: a rising edge needs the previous value; none in cycle 1.
  expr edge_of(const std::string& state_name, const expr& now);

  // The values of this cycle, as each element is encoded.
  void set_cause_active(int id, const expr& active) { cause_active_.emplace(id, active); }
  void set_effect_active(int id, const expr& active) { effect_active_.emplace(id, active); }
  void set_effect_tag(int id, int tag, const expr& value) { effect_tag_.emplace(std::make_pair(id, tag), value); }
  // A cause's value in this cycle; nullopt before it is encoded.
  std::optional<expr> evaluated_cause(int id) const {
    auto it = cause_active_.find(id);
    if (it == cause_active_.end()) return std::nullopt;
    return it->second;
  }
  void finish_previous_refs();

 private:
  const model::Matrix& m_;
  model::DependencyGraph graph_;
  expr first_;
  expr cmd_ok_;
  expr gd_;
  std::map<std::size_t, expr> raw_value_, raw_bad_;
  std::map<int, expr> cause_active_;
  std::map<int, expr> effect_active_;
  std::map<std::pair<int, int>, expr> effect_tag_;
  struct PrevRef {
    model::InternalRef ref;
    expr var;
  };
  std::map<std::tuple<int, int, int>, PrevRef> prev_refs_;
};

// What phase 2 leaves for the elements: each one's commands accepted in this
// cycle, and the simulations and tag soft bypasses after them.
struct CommandStates {
  struct CauseCommands {
    expr sb_on;        // soft bypass after commands (before the C.1 expiry check)
    expr sb_start;     // switched on in this cycle (timer starts)
    expr sb_prev;      // state variable
    std::vector<expr> tag_sb;  // tag soft bypass after commands
    expr clear_alarms;
    expr ack;
  };
  struct EffectCommands {
    expr sb_on;
    expr clear_alarms;
    expr reset;   // reset_effect accepted
    expr toggle;  // override_effect / stop_override accepted
  };
  std::map<int, CauseCommands> cause_cmds;
  std::map<int, EffectCommands> effect_cmds;
  std::map<int, expr> clear_first_out;
  std::map<std::string, Simulation> sims;  // by tag_key
  std::vector<std::string> sim_order;      // tag keys in processing order
};

// Phase 2 of M.1: the operator commands as per-cycle inputs, processed as a
// set in the encoding's fixed order (docs/encoding.md "Operator commands");
// the creation order of the command inputs is that order.
class CommandEncoder : public Terms {
 public:
  CommandEncoder(z3::context& ctx, const model::Matrix& m, Encoding& enc, bool guard_cells, const Reads& reads,
                 const std::vector<const model::Cause*>& causes, const std::vector<const model::Effect*>& effects)
      : Terms(ctx, enc, guard_cells), m_(m), reads_(reads), causes_(causes), effects_(effects) {}

  CommandStates encode();

 private:
  // A per-cycle command input, gated by secure write (M.3). Creation order is
  // the processing order (Encoding::canonical_commands).
  expr command(CommandInput ci, const std::string& name) {
    ci.var = ts_.make_inputvar(name, c_.bool_sort());
    enc_.commands.push_back(ci);
    return ci.var && reads_.cmd_ok();
  }
  CommandInput cmd_of(model::CommandOp op) {
    return CommandInput{op, 0, 0, 0, 0, true, "", B(false), std::nullopt};
  }
  // The steps of encode(), in the order the encoding processes them.
  void collect_simulations();
  void make_tag_soft_bypass_states();
  void command_simulate_tag();        // O.8
  void command_stop_simulation();     // O.8
  void command_soft_bypass_cause();   // O.5
  void command_soft_bypass_tag();     // O.6
  void command_soft_bypass_effect();  // O.7
  void commands_without_interplay();  // O.9, O.10, O.1, O.2, O.3
  expr sim_on(const std::string& name);
  expr cause_locked_except(const model::Cause* cz, const std::string& key);

  const model::Matrix& m_;
  const Reads& reads_;
  const std::vector<const model::Cause*>& causes_;    // processed causes in the cone, by id
  const std::vector<const model::Effect*>& effects_;  // processed effects in the cone, by id
  CommandStates out_;
  std::map<std::string, std::vector<const model::Cause*>> readers_;   // tag key -> locked causes (O.6, O.8)
  std::map<std::string, std::vector<const model::Effect*>> writers_;  // tag key -> locked effects (O.8)
  std::map<int, std::vector<expr>> tag_sb_prev_;  // tag soft bypass (O.6): previous cycle, by cause
  std::map<int, std::vector<expr>> tag_sb_;       // ... and at this point of the command sequence
};

// Phase 3 for one cause (encode_cause.cpp): one step per paragraph of C; and
// phase 4, first out (C.11), once every cause is encoded.
class CauseEncoder : public Terms {
 public:
  CauseEncoder(z3::context& ctx, const model::Matrix& m, Encoding& enc, bool guard_cells, Reads& reads,
               const CommandStates& commands)
      : Terms(ctx, enc, guard_cells), m_(m), reads_(reads), cmds_(commands) {}

  void build_cause(const model::Cause& cz);
  void build_first_out();  // C.11

 private:
  struct CauseSoftBypass {
    expr on;        // after the C.1 expiry check
    expr timeout;   // `bypass_timeout`
    expr prealarm;  // `bypass_prealarm`
  };
  struct CauseTags {
    std::vector<expr> values, bads;  // per tag position (C.2)
  };
  struct CauseVote {
    expr hysteresis_mode;  // prev(TR) of an analog cause (C.4)
    expr tr, tr_strict;    // trip requested, with and without the relaxed threshold
    expr taken_out;        // number of tags taken out (C.3)
    expr tripped;          // number of voting tags tripped
    expr voting;           // the resulting logic (model::Voting)
  };
  struct CauseTime {
    expr tm;
    expr timer_running;
  };
  struct CauseActive {
    expr bypassed, inhibited, ack_latch, active;
  };
  CauseSoftBypass cause_soft_bypass(const model::Cause& cz);                     // C.1
  CauseTags cause_tag_values(const model::Cause& cz);                            // C.2
  CauseVote cause_voting(const model::Cause& cz, const CauseTags& tags);         // C.3, C.4
  expr cause_delta_alarm(const model::Cause& cz, const CauseTags& tags);         // C.5
  expr cause_prewarning(const model::Cause& cz, const CauseTags& tags);          // C.5
  CauseTime cause_time_function(const model::Cause& cz, const expr& tr);         // C.6
  CauseActive cause_latch_and_active(const model::Cause& cz, const expr& soft_bypass,
                                     const expr& tr, const expr& tm);            // C.7, C.8
  void name_cause_terms(const model::Cause& cz, const CauseSoftBypass& sb, const CauseVote& vote,
                        expr delta_alarm, expr prewarning, const CauseTime& time,
                        const CauseActive& a);                                   // C.9

  const model::Matrix& m_;
  Reads& reads_;
  const CommandStates& cmds_;
  std::map<int, std::vector<std::pair<int, expr>>> first_out_groups_;
};

// Phase 3 for one effect (encode_effect.cpp): one step per paragraph of E.
class EffectEncoder : public Terms {
 public:
  EffectEncoder(z3::context& ctx, const model::Matrix& m, Encoding& enc, bool guard_cells, Reads& reads,
                const CommandStates& commands)
      : Terms(ctx, enc, guard_cells), m_(m), reads_(reads), cmds_(commands) {}

  void build_effect(const model::Effect& ef);

 private:
  struct EffectRequests {
    expr N, S, V, R;                            // req_N .. req_R (E.2)
    std::vector<std::pair<int, expr>> linked;   // (cause id, active) of every processed intersection
  };
  struct EffectReads {
    expr bypassed;              // hard or soft (E.1)
    expr toggle;                // override_effect / stop_override, or the reset tag's edge
    expr output_delay_before;   // prev(output_delay_running)
  };
  struct EffectOverride {
    expr running;        // `override_active`
    expr was_running;    // at the start of the cycle
    expr failed_timeout, failed_cause, prealarm;
    expr reset;          // a reset request reaching the latches (E.4)
  };
  struct EffectLatches {
    expr s, r;
  };
  struct EffectOutputDelay {
    expr output_state;  // OS
    expr running;       // `output_delay_running`
  };
  struct EffectOutputs {
    bool pass = false, has_mask = false;
    expr mask;
  };
  EffectRequests effect_requests(const model::Effect& ef);                          // E.2
  EffectReads effect_reads(const model::Effect& ef);                                // E.1
  EffectOverride effect_override(const model::Effect& ef, const EffectRequests& req,
                                 const EffectReads& reads);                         // E.3
  EffectLatches effect_latches(const model::Effect& ef, const EffectRequests& req,
                               const EffectReads& reads, const EffectOverride& ov);  // E.4, E.5
  EffectOutputDelay effect_output_delay(const model::Effect& ef, const expr& active,
                                        const expr& output_delay_before);           // E.7
  EffectOutputs effect_outputs(const model::Effect& ef, const expr& output_state);  // E.8-E.10
  void name_effect_terms(const model::Effect& ef, const EffectRequests& req, const EffectReads& reads,
                         const EffectOverride& ov, const EffectLatches& latches, const expr& active,
                         const EffectOutputDelay& delay, const EffectOutputs& out);  // E.11

  const model::Matrix& m_;
  Reads& reads_;
  const CommandStates& cmds_;
};

// encode(): the cone of the roots, its phases in the order of M.1, and the
// elements of phase 3 in the dependency graph's evaluation order (I.4).
class Builder {
 public:
  Builder(z3::context& ctx, const model::Matrix& m, Encoding& enc, bool guard_cells = false)
      : c_(ctx), m_(m), enc_(enc), guard_cells_(guard_cells) {}

  void build(const std::vector<Node>& roots);

 private:
  z3::context& c_;
  const model::Matrix& m_;
  Encoding& enc_;
  bool guard_cells_ = false;
};

}  // namespace cemv::encoder::detail
