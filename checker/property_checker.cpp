#include "checker/property_checker.hpp"

#include <filesystem>
#include <limits>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_map>

#include "checker/check/recheck.hpp"
#include "checker/context_pool.hpp"
#include "checker/counterexample.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/engines/solving.hpp"
#include "checker/property_problem.hpp"
#include "checker/replay.hpp"
#include "checker/support.hpp"
#include "encoder/encode.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario_writer.hpp"
#include "model/text.hpp"
#include "properties/evaluator.hpp"
#include "properties/monitor.hpp"
#include "properties/shape.hpp"

namespace cemv::checker {

namespace {

// Random runs tried for a vacuity witness before the engines are asked
// (checker/witness_pool.hpp).
constexpr int kRandomWitnessRuns = 8;

using properties::Expr;
using properties::PropertyKind;

// The observables a property reads, in first-use order: what its
// counterexample's scenario expects and its timing table shows.
void collect_observables(const Expr& e, std::vector<model::Observable>& out) {
  if (e.kind == Expr::Kind::Observable) {
    for (const auto& o : out) if (o.key == e.observable.key) return;
    out.push_back(e.observable);
  }
  for (const auto& a : e.args) collect_observables(a, out);
}

std::vector<model::Observable> observables_read(const properties::PropertyFile& f, const properties::Property& p) {
  std::vector<model::Observable> out;
  collect_observables(p.body, out);
  collect_observables(p.trigger, out);
  collect_observables(p.response, out);
  for (const auto& a : p.assumptions) collect_observables(a.expr, out);
  for (const auto& a : f.assumptions) collect_observables(a.expr, out);
  return out;
}

// A file name for a property's scenario: its name with anything outside
// [A-Za-z0-9._-] replaced, so every property name maps to a safe file.
std::string file_stem(const std::string& name) {
  std::string s;
  for (char c : name) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') ? c : '_';
  return s.empty() ? "property" : s;
}

// The readable table of a replayed run: the inputs that change and the
// property's observables, their value in the first cycle and wherever they
// change ("cycle:value").
std::string timing_table(const model::Matrix& m, const ConcreteTrace& t,
                         const std::vector<model::Observable>& shown) {
  std::ostringstream out;
  model::InputTable table(m);
  auto row = [&](const std::string& label, auto value_at) {
    std::string line = "  " + label + ":";
    std::string last;
    for (std::size_t k = 0; k < t.inputs.size(); ++k) {
      std::string v = value_at(k);
      if (k == 0 || v != last) line += " " + std::to_string(k + 1) + ":" + v;
      last = v;
    }
    out << line << "\n";
  };
  for (std::size_t i = 0; i < table.size(); ++i) {
    bool changes = false;
    for (std::size_t k = 1; k < t.inputs.size(); ++k)
      changes |= t.inputs[k].tags[i].value != t.inputs[0].tags[i].value ||
                 t.inputs[k].tags[i].bad_quality != t.inputs[0].tags[i].bad_quality;
    if (!changes) continue;
    const auto& tag = table.tags()[i];
    row(tag.name, [&](std::size_t k) {
      const auto& v = t.inputs[k].tags[i];
      std::string s = tag.kind == model::TagKind::Bool ? (v.value != 0.0f ? "1" : "0") : model::float_text(v.value);
      return v.bad_quality ? s + "(bad)" : s;
    });
  }
  for (std::size_t k = 0; k < t.inputs.size(); ++k)
    for (const auto& c : t.inputs[k].commands)
      out << "  command in cycle " << k + 1 << ": " << formats::command_text(m, c) << "\n";
  const auto all = model::observables(m);
  for (const auto& o : shown)
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all[i].key == o.key)
        row(o.key, [&](std::size_t k) {
          int v = t.observables[k][i];
          return o.type == model::FieldType::Voting ? std::string(model::to_string(static_cast<model::Voting>(v)))
                                                     : std::to_string(v);
        });
  return out.str();
}

// The concrete evaluator's judgement of a replayed run (properties/evaluator.hpp).
struct Judgement {
  bool violated = false;   // Invariant/Never/Response: violated; Reachable: witnessed
  int cycle = -1;          // 0-based cycle of the violation or witness
};
properties::Trace as_property_trace(const ConcreteTrace& t) {
  properties::Trace trace;
  for (std::size_t k = 0; k < t.inputs.size(); ++k) trace.push_back({t.inputs[k], t.observables[k]});
  return trace;
}

Judgement judge(const model::Matrix& m, const properties::PropertyFile& f, const properties::Property& p,
                const ConcreteTrace& t) {
  properties::Evaluation ev = properties::Evaluator(m).evaluate(p, f.assumptions, as_property_trace(t));
  Judgement j;
  // Only the judged prefix counts: the cycles in which every assumption held.
  bool found = p.kind == PropertyKind::Reachable ? ev.holds : !ev.holds;
  if (found && ev.cycle) {
    j.violated = true;
    j.cycle = static_cast<int>(*ev.cycle);
  }
  return j;
}

}  // namespace

PropertyChecker::PropertyChecker(const model::Matrix& m, const properties::PropertyFile& file,
                                 const properties::Property& p, const CheckOptions& options, EarlyAnswer early)
    : m_(m), file_(file), p_(p), options_(options), roots_(properties::property_roots(p, file.assumptions, m)),
      early_(std::move(early)) {
  has_antecedent_ = early_.facts.has_antecedent;
  preferred_ = early_.facts.preferred;
  cone_space_ = early_.facts.space;
}

PropertyChecker::PropertyChecker(const model::Matrix& m, const properties::PropertyFile& file,
                                 const properties::Property& p, const CheckOptions& options)
    : m_(m), file_(file), p_(p), options_(options), roots_(properties::property_roots(p, file.assumptions, m)) {
  // Whether the monitor has an antecedent (a trigger, the left side of an
  // implication) is the monitor's to say: ask it once, in a scratch context.
  PooledContext ctx;
  auto enc = encoder::encode(ctx, m_, roots_);
  has_antecedent_ = properties::compile_monitor(*enc, p_, file_.assumptions).antecedent.has_value();
  // Input names are the same in every encoding of this matrix: the cone's
  // (with the inputs the monitor added) names every input a sliced problem
  // has; the unsliced retry leaves the others free.
  preferred_ = plant_at_rest({{enc.get(), &m_}});
  std::vector<std::string> tags;
  for (std::size_t i = 0; i < enc->tag_value.size(); ++i)
    if (enc->tag_value[i] || enc->tag_bad[i]) tags.push_back(enc->inputs.tags()[i].name);
  std::vector<model::Command> commands;
  for (const auto& c : enc->commands) commands.push_back(c.command());
  cone_space_ = run_space(m_, nullptr, tags, commands);
  if (commands.empty()) cone_space_.commands.clear();  // a cone without commands: runs change inputs only
}

ProblemFactory PropertyChecker::factory(const model::Matrix& m, Goal goal, bool sliced) const {
  ProblemOptions o;
  o.goal = goal;
  o.sliced = sliced;
  o.modify_encoding = options_.modify_encoding;
  return property_problem(m, file_, p_, o);
}

ProverResult PropertyChecker::ask(const model::Matrix& m, Goal goal, bool sliced, const Limits& limits) const {
  const CheckBudgets& b = options_.budgets;
  if (goal == Goal::Assumptions) {
    // One cycle decides it: a run either starts with the assumptions holding
    // or there is none. Plain BMC to depth 0.
    PooledContext ctx;
    OwnedProblem op = factory(m, goal, sliced)(ctx);
    return Bmc{}.prove(op.problem, limits.with_work(b.vacuity).with_depth(0));
  }
  PortfolioOptions o;
  o.preferred = preferred_;
  o.quick_work = b.quick;
  o.engine_work = goal == Goal::Property ? b.engine : b.vacuity;
  o.shrink_work = b.shrink;
  if (goal == Goal::Property) {
    if (!options_.engines.empty()) o.engines = options_.engines;
    o.wide_engines = options_.engines_when_wide;
    if (options_.max_k >= 0) o.max_k = options_.max_k;
    // Localized to the elements the property names, unless the caller names
    // others: a proof about one effect's own timers (an output delay held
    // back) needs the state of that effect, not of the hundreds of state
    // variables of its cone (checker/localize.hpp; the proof is re-checked
    // on the whole cone).
    o.localize_keep = keep_elements(options_.localize_to.empty() ? roots_ : options_.localize_to);
    if (options_.shrink_max_cycles >= 0) o.shrink_max_cycles = static_cast<std::size_t>(options_.shrink_max_cycles);
  }
  // Only the property's own counterexample is shown; the witness that an
  // antecedent can hold needs no readable form.
  if (goal != Goal::Property) o.shrink_work = 0;
  // An antecedent is expected to be reachable, usually within a few delays,
  // and so is what a cover asks for: BMC first, then the accelerated
  // unrolling for a witness that holds a timer (an 18,000-cycle override),
  // and only then the engines that prove it unreachable.
  // A witness that cannot come before a cycle beyond BMC's depth (a `held`
  // of 18,000 cycles) is the accelerated unrolling's alone.
  const bool witness_expected =
      goal == Goal::Antecedent || (goal == Goal::Property && p_.kind == PropertyKind::Reachable);
  if (witness_expected && (goal != Goal::Property || options_.engines.empty())) {
    const properties::Expr* a = properties::antecedent_of(p_);
    if (a && properties::earliest_cycle(*a) > o.bmc_depth)
      o.engines = {Method::AcceleratedBmc, Method::KInduction, Method::InvariantsInduction, Method::Pdr};
    else
      o.engines = {Method::Bmc, Method::AcceleratedBmc, Method::KInduction, Method::InvariantsInduction, Method::Pdr};
    // A witness on the elements the question names, the rest of the cone
    // free, counts when its inputs reach the same on the whole cone.
    o.localize_keep = keep_elements(options_.localize_to.empty() ? roots_ : options_.localize_to);
    o.localized_engines = {Method::Bmc, Method::AcceleratedBmc};
  }
  return Portfolio(factory(m, goal, sliced), o).run(limits);
}

bool PropertyChecker::confirm_trace(const ProverResult& r, bool sliced, PropertyResult& out) const {
  PooledContext ctx;
  OwnedProblem op = factory(m_, Goal::Property, sliced)(ctx);
  const auto& enc = *std::static_pointer_cast<encoder::Encoding>(op.owner);
  // The portfolio has made the trace readable (inputs at rest where the
  // violation allows) and re-checked it on this problem.
  std::vector<model::CycleInput> inputs = cycle_inputs(r.cex, enc, m_);
  ConcreteTrace runtime_trace = run_on_runtime(m_, inputs);
  runs_.push_back(as_property_trace(runtime_trace));
  Judgement j = judge(m_, file_, p_, runtime_trace);
  if (!j.violated) {
    out.reason = describe_disagreement(m_, runtime_trace, run_on_encoding(enc, m_, inputs));
    return false;
  }
  report_trace(std::move(runtime_trace), j.cycle, out);
  return true;
}

bool PropertyChecker::answered_by_run(const std::vector<model::CycleInput>& inputs, Method method,
                                      bool agree_or_throw, PropertyResult& out) const {
  ConcreteTrace runtime_trace = run_on_runtime(m_, inputs);
  runs_.push_back(as_property_trace(runtime_trace));
  Judgement j = judge(m_, file_, p_, runtime_trace);
  if (!j.violated) return false;
  // The runtime and the concrete evaluator found it; the encoding and the
  // monitor must agree, as for an engine's trace the other way round.
  std::vector<model::CycleInput> prefix(inputs.begin(), inputs.begin() + j.cycle + 1);
  PooledContext ctx;
  OwnedProblem op = factory(m_, Goal::Property, true)(ctx);
  const auto& enc = *std::static_pointer_cast<encoder::Encoding>(op.owner);
  // A command the slice has no input for acts on an element outside the
  // cone, or on something the encoding does not model: left out of the
  // replay, and if the replay then disagrees, the run is left to the
  // engines rather than taken for a disagreement of runtime and encoding.
  std::size_t dropped = 0;
  std::optional<Trace> t = encoded_trace(prefix, enc, *op.problem.ts, &dropped);
  if (!t) return false;  // inputs the encoding does not map: leave it to the engines
  try {
    check::replay_counterexample(op.problem, *t);
  } catch (const InternalError& e) {
    if (dropped > 0 || !agree_or_throw) return false;
    throw InternalError("the runtime " + std::string(p_.kind == PropertyKind::Reachable ? "witnesses" : "violates") +
                        " property " + p_.name + " (" + file_.file_name + ") in cycle " + std::to_string(j.cycle + 1) +
                        " of a " + to_string(method) + ", the encoding does not: " + e.what() + "\n" +
                        describe_disagreement(m_, runtime_trace, run_on_encoding(enc, m_, prefix)));
  }
  report_trace(std::move(runtime_trace), j.cycle, out);
  out.method = to_string(method);
  return true;
}

bool PropertyChecker::directed_counterexample(PropertyResult& out) const {
  if (p_.kind == PropertyKind::Reachable) return false;
  for (const auto& inputs : options_.directed_runs)
    if (answered_by_run(inputs, Method::DirectedRun, true, out)) return true;
  return false;
}

bool PropertyChecker::early_answer(PropertyResult& out) {
  if (early_.proof) {
    // Proved by the group on its shared encoding, and re-checked there in a
    // fresh context (checker/cone_group.hpp).
    const ProverResult& r = *early_.proof;
    sliced_ = true;
    proof_ = r;
    out.method = r.method_text();
    out.depth = r.k;
    out.work = r.work;
    out.invariant = r.invariant.text();
    out.verdict = p_.kind == PropertyKind::Reachable ? PropertyVerdict::Unreachable : PropertyVerdict::Proved;
    return true;
  }
  // A run of the group's (a random run, a shallow BMC witness): a run of the
  // group's slice that the runtime does not reproduce is left to the engines.
  if (!early_.run.empty() && answered_by_run(early_.run, early_.run_method, false, out)) {
    out.verdict = p_.kind == PropertyKind::Reachable ? PropertyVerdict::Reachable : PropertyVerdict::Falsified;
    return true;
  }
  return false;
}

void PropertyChecker::report_trace(ConcreteTrace runtime_trace, int violation_cycle, PropertyResult& out) const {
  // The evaluator's first violation ends the run: cut what follows it.
  std::size_t length = static_cast<std::size_t>(violation_cycle) + 1;
  runtime_trace.inputs.resize(length);
  runtime_trace.observables.resize(length);
  const std::vector<model::CycleInput>& inputs = runtime_trace.inputs;
  out.violation_cycle = violation_cycle;
  out.depth = static_cast<int>(length);
  const auto shown = observables_read(file_, p_);
  for (const auto& o : shown) out.matters.push_back(o.key);
  out.timing_table = timing_table(m_, runtime_trace, shown);
  if (!options_.out_dir.empty()) {
    std::vector<formats::ExpectedValue> expect;
    const auto all = model::observables(m_);
    for (const auto& o : shown)
      for (std::size_t i = 0; i < all.size(); ++i)
        if (all[i].key == o.key) expect.push_back({o.key, o.type, runtime_trace.observables.back()[i]});
    std::string what = p_.kind == PropertyKind::Reachable ? "Witness of" : "Counterexample to";
    std::string text = formats::scenario_text(
        m_, formats::checked_at_end(inputs, what + " property " + p_.name + " (" + file_.file_name + ")", expect));
    std::filesystem::path path = std::filesystem::path(options_.out_dir) / (file_stem(p_.name) + ".scenario.json");
    write_text_atomically(path, text);
    out.scenario_file = path.string();
  }
  out.trace = std::move(runtime_trace);
}

PropertyChecker::Vacuity PropertyChecker::vacuity(const WitnessPool& known, WitnessPool& group,
                                                  const Limits& limits) const {
  Vacuity v;
  // A witness that the antecedent can hold is a run in which the assumptions
  // hold too: most properties need no more than that one question.
  if (known.witnesses(m_, p_, file_.assumptions, has_antecedent_)) return v;
  if (group.witnesses(m_, p_, file_.assumptions, has_antecedent_)) return v;
  // Random runs last a few hundred cycles: an antecedent that cannot hold
  // that early is left to the engines.
  const properties::Expr* antecedent = properties::antecedent_of(p_);
  WitnessPool mine;
  if (!early_.runs_tried &&
      (!antecedent || properties::earliest_cycle(*antecedent) < static_cast<long long>(WitnessPool::kMaxRunCycles)) &&
      mine.search(m_, p_, file_.assumptions, has_antecedent_, cone_space_, kRandomWitnessRuns))
    return v;
  std::optional<ProverResult> t;
  if (has_antecedent_) {
    t = ask(m_, Goal::Antecedent, true, limits);
    if (t->verdict == Verdict::Falsified) {
      // Kept for the group's other members: their antecedents are often
      // this one with another cause (an XooN's members).
      PooledContext ctx;
      OwnedProblem op = factory(m_, Goal::Antecedent, true)(ctx);
      const auto& enc = *std::static_pointer_cast<encoder::Encoding>(op.owner);
      group.add(as_property_trace(run_on_runtime(m_, cycle_inputs(t->cex, enc, m_))));
      return v;
    }
  }
  // Plain BMC to depth 0 answers "bound reached" exactly when no first cycle
  // satisfies the assumptions; any other unknown leaves the question open.
  ProverResult a = ask(m_, Goal::Assumptions, true, limits);
  if (a.verdict == Verdict::Unknown && a.reason == UnknownReason::BoundReached) {
    v.vacuous = "the assumptions cannot hold in the first cycle";
    return v;
  }
  if (a.verdict != Verdict::Falsified) {
    v.undecided = "vacuity not decided (" + a.reason_text() + ")";
    return v;
  }
  if (!t) return v;
  if (t->verdict == Verdict::Proved)
    v.vacuous = p_.kind == PropertyKind::Response ? "the trigger can never hold" : "the antecedent can never hold";
  else
    v.undecided = "vacuity not decided: whether the " +
                  std::string(p_.kind == PropertyKind::Response ? "trigger" : "antecedent") +
                  " can hold (" + t->reason_text() + ")";
  return v;
}

bool PropertyChecker::needs_vacuity(const PropertyResult& r) const {
  return options_.vacuity && (r.verdict == PropertyVerdict::Proved || r.verdict == PropertyVerdict::Unreachable);
}

void PropertyChecker::settle_vacuity(PropertyResult& r, const WitnessPool& known, WitnessPool& group,
                                     const Limits& limits) const {
  if (!needs_vacuity(r) || early_.vacuity_witnessed) return;
  const auto start = Clock::now();
  Vacuity v = vacuity(known, group, limits);
  r.seconds += seconds_since(start);
  if (v.vacuous) {
    r.verdict = PropertyVerdict::Vacuous;
    r.reason = *v.vacuous;
    r.support.clear();
    return;
  }
  if (v.undecided) r.notes.push_back(*v.undecided);
}

bool PropertyChecker::needs_support(const PropertyResult& r) const {
  return options_.support && options_.support_mode != SupportMode::Off && sliced_ &&
         r.verdict == PropertyVerdict::Proved && proof_.has_value();
}

PropertyResult PropertyChecker::decide(const Limits& limits) {
  PropertyResult out;
  const auto start = Clock::now();
  out.name = p_.name;
  out.description = p_.description;
  out.kind = properties::to_string(p_.kind);
  out.line = p_.loc.line;
  out.column = p_.loc.column;
  out.file = file_.file_name;
  out.notes = p_.notes;
  auto finish = [&](PropertyVerdict v) {
    out.verdict = v;
    out.seconds = seconds_since(start);
    return out;
  };
  auto interrupted = [&] {
    PropertyResult cut = out;
    cut.verdict = PropertyVerdict::Unknown;
    cut.unknown = UnknownReason::TimeLimit;
    cut.reason = to_string(UnknownReason::TimeLimit);
    cut.method.clear();
    cut.trace.reset();
    cut.scenario_file.clear();
    cut.timing_table.clear();
    cut.seconds = seconds_since(start);
    return cut;
  };
  try {
    if (early_answer(out)) return finish(out.verdict);
    if (directed_counterexample(out)) return finish(PropertyVerdict::Falsified);
    if (options_.directed_runs_only) {
      out.unknown = UnknownReason::NoDirectedRun;
      out.reason = to_string(out.unknown);
      return finish(PropertyVerdict::Unknown);
    }
    ProverResult r = ask(m_, Goal::Property, true, limits);
    sliced_ = true;
    // The portfolio has re-checked its answer in a fresh context (a proof's
    // invariant and step re-proved, a trace re-simulated on the encoding): an
    // engine bug stops there. The runtime replay below catches encoder bugs.
    if (r.verdict == Verdict::Falsified && !confirm_trace(r, true, out)) {
      // A slice over-approximates what lies outside the cone (first-out
      // groups, mutual locks: docs/encoding.md "Slices"), so a slice's trace
      // may not be a run of the whole matrix. The full encoding is exact:
      // its trace must replay.
      sliced_ = false;
      r = ask(m_, Goal::Property, false, limits);
      if (r.verdict == Verdict::Falsified && !confirm_trace(r, false, out))
        throw InternalError("the runtime does not reproduce the counterexample to property " + p_.name + " (" +
                            file_.file_name + ")\n" + out.reason);
    }
    if (limits.interrupted()) return interrupted();
    out.method = r.method_text();
    out.depth = r.verdict == Verdict::Falsified ? out.depth : r.k;
    out.work = r.work;
    switch (r.verdict) {
      case Verdict::Falsified:
        return finish(p_.kind == PropertyKind::Reachable ? PropertyVerdict::Reachable : PropertyVerdict::Falsified);
      case Verdict::Proved:
        out.invariant = r.invariant.text();
        proof_ = r;
        return finish(p_.kind == PropertyKind::Reachable ? PropertyVerdict::Unreachable : PropertyVerdict::Proved);
      case Verdict::Unknown:
        out.unknown = r.reason;
        out.reason = r.reason_text();
        if (!r.engines.empty()) out.notes.push_back("engines: " + r.engines);
        return finish(PropertyVerdict::Unknown);
    }
  } catch (const Interrupted&) {
    return interrupted();
  }
  return finish(PropertyVerdict::Unknown);
}

std::vector<SupportElement> unsupported_elements(const model::Matrix& m,
                                                 const std::vector<PropertyResult>& results) {
  std::set<std::string> supported;
  for (const auto& r : results)
    for (const auto& e : r.support) supported.insert(e.key);
  std::vector<model::Node> everything;
  for (const auto& c : m.causes) everything.push_back({model::Node::Kind::Cause, c.id});
  for (const auto& e : m.effects) everything.push_back({model::Node::Kind::Effect, e.id});
  std::vector<SupportElement> out;
  for (const auto& d : candidate_deletions(m, everything))
    if (!supported.count(d.element.key)) out.push_back(d.element);
  return out;
}

}  // namespace cemv::checker
