// Section E of docs/semantics.md as statements: one block of the body per
// processed effect, in the evaluation order. The effect's soft bypass and the
// simulation of its outputs are not in the program (the map declares them
// unused).
#include <algorithm>

#include "plc_export/export.hpp"
#include "plc_export/generator.hpp"
#include "plc_export/st_build.hpp"

namespace cemv::plc_export {

namespace {

using model::IntersectionType;
using plc::BinaryOp;
using plc::Expr;
using plc::Statement;
using plc::Type;

const char* type_letter(IntersectionType t) {
  switch (t) {
    case IntersectionType::N: return "N";
    case IntersectionType::S: return "S";
    case IntersectionType::V: return "V";
    case IntersectionType::R: return "R";
    default: return "?";
  }
}

struct Link {
  int cause = 0;
  IntersectionType type = IntersectionType::N;
  bool xoon = false;
};

}  // namespace

void Generator::effect(const model::Effect& e) {
  const std::string E = effect_var.at(e.id);
  const std::string label = element_label(e);
  std::vector<Statement> out;

  // E.2 links: processed intersections with processed causes; the XooN
  // assignment's X is the smallest given, its type the first cause's.
  std::vector<Link> links;
  bool has_xoon = false;
  int xoon_x = 0;
  IntersectionType xoon_type = IntersectionType::N;
  for (const auto* x : m.intersections_of_effect(e.id)) {
    if (!model::is_processed(x->type) || !cause_var.count(x->cause)) continue;
    links.push_back({x->cause, x->type, x->xoon.has_value()});
    if (x->xoon) {
      xoon_x = has_xoon ? std::min(xoon_x, *x->xoon) : *x->xoon;
      if (!has_xoon) xoon_type = x->type;
      has_xoon = true;
    }
  }
  auto present = [&](IntersectionType t) {
    return std::any_of(links.begin(), links.end(), [&](const Link& l) { return l.type == t; });
  };
  const bool has_s = present(IntersectionType::S), has_r = present(IntersectionType::R);
  const bool has_v = present(IntersectionType::V);
  const bool override_possible = e.override_time.has_value() && (has_v || has_r);

  // E.1 reads.
  const bool hard_bypass = e.bypass_tag && !e.bypass_tag->empty();
  const Expr bypassed = hard_bypass ? tag_bool(*e.bypass_tag) : st::boolean(false);
  const bool needs_delay_running = override_possible || has_s || has_r;
  std::string delay_running;
  if (e.output_delay_ms > 0 && needs_delay_running)
    delay_running = local(E + "_DELAY_RUNNING", Type::Bool, "E.7 output delay running; read as the previous scan's");
  const Expr delay_running_prev = delay_running.empty() ? st::boolean(false) : st::var(delay_running);

  std::string running, was_running, req_r_prev, scans_var;
  std::map<int, std::string> saw;
  std::string section = "Effect " + std::to_string(e.id) + " " + e.name +
                        (e.description.empty() ? "" : " (" + e.description + ")") + " [6.4, 6.5.2].";
  if (override_possible) {
    running = local(E + "_OVERRIDE", Type::Bool, "E.3 override running");
    was_running = local(E + "_OVERRIDE_WAS", Type::Bool, "E.3 override running at the end of the previous scan");
    scans_var = local(E + "_OVERRIDE_SCANS", Type::Dint, "scans since the override started");
    out.push_back(st::assign(was_running, st::var(running), section + " E.3: the override of the previous scan."));
    section.clear();
    if (has_r) {
      req_r_prev = local(E + "_REQ_R_PREV", Type::Bool, "the R request of the previous scan (E.5)");
    }
    if (!group_deactivation.empty())
      out.push_back(st::if_(st::var(group_deactivation), {st::assign(running, st::boolean(false))},
                            "M.2: group deactivation ends the override."));
  }
  std::string reset_edge;
  if (e.reset_tag && !e.reset_tag->empty()) {
    const std::string prev = local(E + "_RESET_TAG_PREV", Type::Bool,
                                   e.reset_tag.value() + " in the previous scan; TRUE at start-up: no edge in scan 1 (T.4)",
                                   plc::Literal{Type::Bool, 1, 0.0f});
    reset_edge = local(E + "_RESET_EDGE", Type::Bool, "E.1 rising edge of the reset tag");
    out.push_back(st::assign(reset_edge, st::and_(tag_bool(*e.reset_tag), st::not_(st::var(prev))),
                             section + " E.1: the rising edge of the reset tag " + *e.reset_tag + " (T.4)."));
    section.clear();
    out.push_back(st::assign(prev, tag_bool(*e.reset_tag)));
  }

  // E.2 requests.
  std::map<IntersectionType, Expr> req;
  for (IntersectionType t : {IntersectionType::N, IntersectionType::S, IntersectionType::V, IntersectionType::R}) {
    if (!present(t)) continue;
    std::vector<Expr> terms;
    std::string causes;
    for (const Link& l : links)
      if (l.type == t && !l.xoon) {
        terms.push_back(st::var(cause_var.at(l.cause)));
        causes += (causes.empty() ? "" : ", ") + std::to_string(l.cause);
      }
    std::string text = std::string("E.2 ") + type_letter(t) + " request";
    if (!causes.empty()) text += " from causes " + causes;
    if (has_xoon && xoon_type == t) {
      Expr sum;
      std::string members;
      bool first = true;
      for (const Link& l : links) {
        if (!l.xoon) continue;
        Expr term = st::sel(st::var(cause_var.at(l.cause)), st::integer(0, Type::Int), st::integer(1, Type::Int), Type::Int);
        sum = first ? std::move(term) : st::binary(BinaryOp::Add, std::move(sum), std::move(term), Type::Int);
        first = false;
        members += (members.empty() ? "" : ", ") + std::to_string(l.cause);
      }
      int count = 0;
      for (const Link& l : links) count += l.xoon ? 1 : 0;
      terms.push_back(st::binary(BinaryOp::Ge, std::move(sum), st::integer(xoon_x, Type::Int), Type::Bool));
      text += (causes.empty() ? "" : ", or ") + std::string(" ") + std::to_string(xoon_x) + "oo" + std::to_string(count) +
              " of causes " + members;
    }
    const std::string v = local(E + "_REQ_" + type_letter(t), Type::Bool, std::string("E.2 ") + type_letter(t) + " request");
    if (t == IntersectionType::R && !req_r_prev.empty()) out.push_back(st::assign(req_r_prev, st::var(v)));
    out.push_back(st::assign(v, st::any(std::move(terms)), section.empty() ? text + "." : section + " " + text + "."));
    section.clear();
    req[t] = st::var(v);
  }
  auto request = [&](IntersectionType t) { return req.count(t) ? req[t] : st::boolean(false); };

  // E.3 override, E.4 reset requests.
  Expr toggle = reset_edge.empty() ? st::boolean(false) : st::var(reset_edge);
  if (auto it = override_var.find(e.id); it != override_var.end())
    toggle = st::or_(std::move(toggle), st::or_(command(it->second), command(stop_override_var.at(e.id))));
  Expr reset_command = st::boolean(false);
  if (auto it = reset_var.find(e.id); it != reset_var.end()) reset_command = command(it->second);
  std::string reset_request;
  if (override_possible) {
    const std::int64_t d = scans(static_cast<std::uint64_t>(e.override_time->max_s) * 1000u, label);
    std::vector<Expr> ends = {st::binary(BinaryOp::Ge, st::var(scans_var, Type::Dint), st::integer(d), Type::Bool)};
    std::vector<Statement> start = {st::assign(running, st::boolean(true)), st::assign(scans_var, st::integer(0))};
    for (const Link& l : links) {
      const std::string c = cause_var.at(l.cause);
      if (saw.count(l.cause)) continue;
      saw[l.cause] = local(E + "_OVERRIDE_SAW_" + c, Type::Bool, "cause " + std::to_string(l.cause) +
                                                                   " was active when the override started (E.3)");
      ends.push_back(st::and_(st::var(c), st::not_(st::var(saw[l.cause]))));
      start.push_back(st::assign(saw[l.cause], st::var(c)));
    }
    ends.push_back(st::not_(st::or_(request(IntersectionType::V), request(IntersectionType::R))));
    out.push_back(st::if_(
        st::var(running),
        {st::assign(scans_var, st::binary(BinaryOp::Add, st::var(scans_var, Type::Dint), st::integer(1), Type::Dint)),
         st::if_(st::any(ends), {st::assign(running, st::boolean(false))})},
        "E.3 step 1 [6.4.5, 13.2]: a running override ends after " + std::to_string(d) +
            " scans, when a linked cause that was not active at its start becomes active, or when neither V nor R "
            "is requested."));
    if (has_s || has_r) {
      reset_request = local(E + "_RESET_REQUEST", Type::Bool, "E.4 reset request of this scan");
      out.push_back(st::assign(reset_request, reset_command));
    }
    std::vector<plc::Branch> branches;
    branches.push_back({st::var(running), {st::assign(running, st::boolean(false))}});
    branches.push_back({st::all({st::or_(request(IntersectionType::V), request(IntersectionType::R)), st::not_(bypassed),
                                 st::not_(delay_running_prev)}),
                        start});
    std::vector<Statement> otherwise;
    if (!reset_request.empty()) otherwise.push_back(st::assign(reset_request, st::boolean(true)));
    if (!st::is_false(toggle))
      out.push_back(st::if_(toggle, {st::if_chain(std::move(branches), std::move(otherwise))},
                            "E.3 step 2 [10.7.3.1, 13.2.1]: a toggle request stops a running override, else starts "
                            "one, else is a reset request."));
  } else if (has_s || has_r) {
    Expr any_reset = st::or_(reset_command, toggle);
    if (!st::is_false(any_reset)) {
      reset_request = local(E + "_RESET_REQUEST", Type::Bool, "E.4 reset request of this scan");
      out.push_back(st::assign(reset_request, any_reset,
                               "E.4: a reset request (the reset tag's edge or a command; without an override "
                               "block a toggle is a reset)."));
    }
  }

  // E.4, E.5 latches.
  std::string s_latch, r_latch;
  if (has_s) s_latch = local(E + "_S_LATCH", Type::Bool, "E.5 S latch");
  if (has_r) r_latch = local(E + "_R_LATCH", Type::Bool, "E.5 R latch");
  if (!reset_request.empty()) {
    std::vector<Statement> clear;
    if (has_s) clear.push_back(st::if_(st::not_(request(IntersectionType::S)), {st::assign(s_latch, st::boolean(false))}));
    if (has_r) clear.push_back(st::if_(st::not_(request(IntersectionType::R)), {st::assign(r_latch, st::boolean(false))}));
    out.push_back(st::if_(st::and_(st::var(reset_request), st::not_(delay_running_prev)), std::move(clear),
                          "E.4 [13.2.2]: a reset clears a latch only once its request is gone and no output delay "
                          "runs."));
  }
  if (has_s) out.push_back(st::if_(request(IntersectionType::S), {st::assign(s_latch, st::boolean(true))}, "E.5 latches."));
  if (has_r) out.push_back(st::if_(request(IntersectionType::R), {st::assign(r_latch, st::boolean(true))},
                                   has_s ? std::string() : "E.5 latches."));
  if (has_r && override_possible)
    out.push_back(st::if_(st::all({st::var(was_running), st::var(req_r_prev), st::not_(request(IntersectionType::R))}),
                          {st::assign(r_latch, st::boolean(false))},
                          "E.5 [13.2.1]: no reset is needed when the R request falls during an override."));

  // E.6 active.
  const Expr latch_s = s_latch.empty() ? st::boolean(false) : st::var(s_latch);
  const Expr latch_r = r_latch.empty() ? st::boolean(false) : st::var(r_latch);
  const Expr not_overridden = running.empty() ? st::boolean(true) : st::not_(st::var(running));
  out.push_back(st::assign(
      E,
      st::and_(st::any({request(IntersectionType::N), latch_s,
                        st::and_(st::or_(request(IntersectionType::V), latch_r), not_overridden)}),
               st::not_(bypassed)),
      section + (section.empty() ? "" : " ") + "E.6 active [3.4, 6.4.4]" +
          (hard_bypass ? ", bypassed by " + *e.bypass_tag : std::string()) + "."));
  section.clear();

  // E.7 output delay.
  Expr os = st::var(E);
  if (e.output_delay_ms > 0) {
    const std::string t = timer(E + "_OUTPUT_DELAY", plc::StandardBlock::Ton, "E.7 output delay");
    const std::string state = local(E + "_OUTPUT_STATE", Type::Bool, "E.7 the delayed active state driving the outputs");
    out.push_back(st::call(t, {{plc::Pin::In, st::var(E)}, {plc::Pin::Pt, preset(e.output_delay_ms, label)}},
                           "E.7 output delay [6.4.5, 13.2.4]: the outputs follow once the effect has been active for " +
                               std::to_string(scans(e.output_delay_ms, label)) +
                               " scans, at once in scan 1 after start-up."));
    out.push_back(st::assign(state, st::and_(st::var(E), st::any({st::var(state), st::var(first_scan),
                                                                   st::member(t, plc::Pin::Q)}))));
    if (!delay_running.empty())
      out.push_back(st::assign(delay_running, st::and_(st::var(E), st::not_(st::var(state)))));
    os = st::var(state);
  }

  // E.8, E.9 outputs: one statement per output tag.
  const bool pass = e.process_data && e.process_data->tag && !e.process_data->tag->empty() && e.process_data->pass_through;
  const bool mask = e.process_data && e.process_data->tag && !e.process_data->tag->empty() &&
                    e.process_data->mask_tag && !e.process_data->mask_tag->empty();
  const Expr p = pass || mask ? tag_bool(*e.process_data->tag) : st::boolean(false);
  const Expr mk = mask ? tag_bool(*e.process_data->mask_tag) : st::boolean(false);
  for (std::size_t j = 0; j < e.tags.size(); ++j) {
    const bool ett = e.tags[j].ett;
    const Expr safe = st::boolean(ett);
    const Expr logic = ett ? os : st::not_(os);
    const Expr process = ett ? st::not_(p) : p;
    Expr value;
    std::string how;
    if (pass && mask) {
      value = ett ? st::or_(st::and_(os, st::not_(mk)), process) : st::and_(st::not_(st::and_(os, st::not_(mk))), process);
      how = "pass-through of " + *e.process_data->tag + " while not tripped, masked by " + *e.process_data->mask_tag;
    } else if (pass) {
      value = ett ? st::or_(os, process) : st::and_(st::not_(os), process);
      how = "pass-through of " + *e.process_data->tag + " while not tripped";
    } else if (mask) {
      value = st::or_(st::and_(mk, process), st::and_(st::not_(mk), logic));
      how = "masked by " + *e.process_data->mask_tag + ": then the process value " + *e.process_data->tag;
    } else {
      value = logic;
    }
    (void)safe;
    out.push_back(st::assign(output_var.at({e.id, static_cast<int>(j + 1)}), std::move(value),
                             "E.9 output tag " + std::to_string(j + 1) + " " + e.tags[j].name +
                                 (ett ? " (ETT: TRUE when tripped)" : " (DTT: FALSE when tripped)") +
                                 (how.empty() ? std::string() : ", " + how) + " [6.4.4, 6.4.5, 13.2.5]."));
  }
  for (auto& s : out) body.push_back(std::move(s));
}

}  // namespace cemv::plc_export
