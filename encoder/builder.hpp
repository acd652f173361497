// The builder of encode(), shared by its three source files (encode.cpp:
// inputs, matrix level, commands; encode_cause.cpp; encode_effect.cpp). Not a
// public header: nothing outside encoder/ includes it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <z3++.h>

#include "encoder/encode.hpp"

namespace cemv::encoder::detail {

using model::Node;
using z3::expr;


// Term names start with the element as observable keys spell it
// (model::observable_key), so each observable is the term named by its key.
inline std::string cause_prefix(int id) { return model::to_string(Node{Node::Kind::Cause, id}); }
inline std::string effect_prefix(int id) { return model::to_string(Node{Node::Kind::Effect, id}); }

// T.2: whole cycles of a duration, rounded up, 64-bit.
inline int cycles_of(std::uint64_t ms, std::uint32_t cycle_ms) {
  if (ms == 0 || cycle_ms == 0) return 0;
  return static_cast<int>((ms + cycle_ms - 1) / cycle_ms);
}

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

class Builder {
 public:
  Builder(z3::context& ctx, const model::Matrix& m, Encoding& enc, bool guard_cells = false)
      : c_(ctx), m_(m), enc_(enc), ts_(enc.ts), graph_(m), first_(ctx), cmd_ok_(ctx), gd_(ctx),
        fp32_(ctx.fpa_sort(8, 24)), guard_cells_(guard_cells) {}

  void build(const std::vector<Node>& roots);

 private:
  expr B(bool b) { return c_.bool_val(b); }
  // EncodeOptions::guard_cells: `term` under the activation literal of the
  // cell with support key `key` (made once); unguarded, `term` itself, so
  // that the plain encoding's terms (and its SMT-LIB text) stay as they are.
  expr guarded(const std::string& key, const expr& term) {
    if (!guard_cells_) return term;
    return guard(key) && term;
  }
  expr guard(const std::string& key) {
    for (const auto& [k, g] : enc_.guards)
      if (k == key) return g;
    expr g = c_.bool_const(("guard." + key).c_str());
    enc_.guards.emplace_back(key, g);
    return g;
  }
  expr I(int v) { return c_.int_val(v); }
  expr count(const std::vector<expr>& bs) {
    if (bs.empty()) return I(0);
    expr sum = z3::ite(bs[0], I(1), I(0));
    for (std::size_t i = 1; i < bs.size(); ++i) sum = sum + z3::ite(bs[i], I(1), I(0));
    return sum;
  }
  expr any(const std::vector<expr>& bs) {
    if (bs.empty()) return B(false);  // a nullary (or) prints as a bare symbol
    if (bs.size() == 1) return bs[0];
    z3::expr_vector v(c_);
    for (const auto& b : bs) v.push_back(b);
    return z3::mk_or(v);
  }
  expr bool_state(const std::string& name, bool init) {
    expr v = ts_.make_statevar(name, c_.bool_sort());
    ts_.set_init(v, B(init));
    return v;
  }
  // An elapsed-cycles counter (T.2) saturating at d, with its range lemma.
  expr counter(const std::string& name, int d) {
    expr v = ts_.make_statevar(name, c_.int_sort());
    ts_.set_init(v, I(0));
    ts_.add_lemma(name + ".range", v >= 0 && v <= d);
    return v;
  }
  expr sat_inc(const expr& e, int d) { return z3::ite(e >= d, I(d), e + 1); }
  expr fconst(float v) { return ts_.float_const(v); }
  expr fge(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_geq(c_, a, b)); }
  expr fle(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_leq(c_, a, b)); }
  expr flt(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_lt(c_, a, b)); }
  expr fabs_diff(const expr& a, const expr& b) {
    expr d(c_, Z3_mk_fpa_sub(c_, ts_.rne(), a, b));
    return expr(c_, Z3_mk_fpa_abs(c_, d));
  }
  expr not_nan(const expr& v) { return !expr(c_, Z3_mk_fpa_is_nan(c_, v)); }

  // A per-cycle command input, gated by secure write (M.3). Creation order is
  // the processing order (Encoding::canonical_commands).
  expr command(CommandInput ci, const std::string& name) {
    ci.var = ts_.make_inputvar(name, c_.bool_sort());
    enc_.commands.push_back(ci);
    return ci.var && cmd_ok_;
  }
  CommandInput cmd_of(model::CommandOp op) {
    return CommandInput{op, 0, 0, 0, 0, true, "", B(false), std::nullopt};
  }

  // The raw input of a tag (I.1); created on first use.
  expr raw_value(std::size_t index);
  expr raw_bad(std::size_t index);
  // A Boolean read of a tag slot by `reader` (E.1, C.8, M.2): an internal
  // reference (I.3, I.4) or the raw input value; nullopt reader = matrix level.
  expr bool_read(const std::string& name, const std::optional<Node>& reader);
  expr ref_value(const model::InternalRef& r, const std::optional<Node>& reader);
  expr edge_of(const std::string& state_name, const expr& now);

  void build_matrix_level();
  void build_commands();
  // The steps of build_commands, in the order the encoding processes them.
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

  // Phase 3, one cause (encode_cause.cpp): one step per paragraph of C.
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
  void build_cause(const model::Cause& cz);
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
  void build_first_out();                                                        // C.11

  // Phase 3, one effect (encode_effect.cpp): one step per paragraph of E.
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
  void build_effect(const model::Effect& ef);
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
  void finish_previous_refs();

  z3::context& c_;
  const model::Matrix& m_;
  Encoding& enc_;
  TransitionSystem& ts_;
  model::DependencyGraph graph_;
  expr first_;   // cycle 1 (T.3)
  expr cmd_ok_;  // M.3: commands accepted in this cycle
  expr gd_;      // M.2: group deactivation in this cycle
  z3::sort fp32_;
  bool guard_cells_ = false;
  std::set<Node> cone_;
  std::vector<const model::Cause*> causes_;    // processed causes in the cone, by id
  std::vector<const model::Effect*> effects_;  // processed effects in the cone, by id

  std::map<std::size_t, expr> raw_value_, raw_bad_;
  std::map<std::string, Simulation> sims_;     // by tag_key
  std::vector<std::string> sim_order_;         // tag keys in processing order
  std::map<std::string, std::vector<const model::Cause*>> readers_;   // tag key -> locked causes (O.6, O.8)
  std::map<std::string, std::vector<const model::Effect*>> writers_;  // tag key -> locked effects (O.8)
  std::map<int, std::vector<expr>> tag_sb_prev_;  // tag soft bypass (O.6): previous cycle, by cause
  std::map<int, std::vector<expr>> tag_sb_;       // ... and at this point of the command sequence

  // After phase 2 (commands).
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
  std::map<int, CauseCommands> cause_cmds_;
  std::map<int, EffectCommands> effect_cmds_;
  std::map<int, expr> clear_first_out_;

  std::map<int, expr> cause_active_;
  std::map<int, expr> effect_active_;
  std::map<std::pair<int, int>, expr> effect_tag_;
  struct PrevRef {
    model::InternalRef ref;
    expr var;
  };
  std::map<std::tuple<int, int, int>, PrevRef> prev_refs_;
  std::map<int, std::vector<std::pair<int, expr>>> first_out_groups_;
};

}  // namespace cemv::encoder::detail
