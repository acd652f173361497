// The correspondence of the whole product, found once (shared_proof.hpp).
#include "plc_check/shared_proof.hpp"

#include <algorithm>
#include <deque>
#include <future>
#include <map>
#include <memory>
#include <mutex>

#include "checker/check/recheck.hpp"
#include "checker/reduce.hpp"
#include "formats/matrix_json.hpp"
#include "formats/plc_map.hpp"
#include "model/vocabulary.hpp"
#include "plc/print.hpp"
#include "plc_check/cones.hpp"
#include "plc_check/correspondence.hpp"

namespace cemv::plc_check {

namespace {

using Groups = std::vector<std::vector<std::size_t>>;
using Cones = std::vector<std::vector<std::size_t>>;

// The most state variables (after the reduction) a whole product is tried
// with every candidate (docs/plc.md "A cone group's Houdini"): the generated
// 16 x 16 program's group has 363, the 32 x 32's 1,047.
constexpr std::size_t kWholeProductStates = 512;

// The goods of `qs` in `reduced`'s terms, and `reduced`: the product of
// `qs` reduced so that each question's relation stays in the cone.
checker::OwnedProblem reduce_product(const checker::ProblemFactory& make, z3::context& ctx, std::vector<z3::expr>& goods) {
  const checker::OwnedProblem original = make(ctx);
  goods = std::static_pointer_cast<ProductProblem>(original.owner)->goods;
  return checker::reduce_with(original, goods);
}

// The questions in groups whose cones overlap (cones.hpp), on the product of
// every question reduced.
Groups group_questions(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                       const ResolvedMap& map, const std::vector<OutputQuestion>& qs, Relation relation) {
  z3::context ctx;
  std::vector<z3::expr> goods;
  const checker::OwnedProblem reduced = reduce_product(product_factory(m, program, pou, map, qs, relation), ctx, goods);
  return overlapping(cones_of(*reduced.problem.ts, goods));
}

// The proof of one group's questions at once, each with the candidates of
// its own cone.
SharedProof prove_group(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                        const ResolvedMap& map, const std::vector<OutputQuestion>& qs, const CheckOptions& o,
                        bool whole = false) {
  SharedProof out;
  if (qs.size() < 2) return out;  // one output: its own decision is the same product
  const checker::ProblemFactory make = product_factory(m, program, pou, map, qs, o.relation);
  z3::context ctx;
  std::vector<z3::expr> goods;
  const checker::OwnedProblem reduced = reduce_product(make, ctx, goods);
  // The whole product's candidates grow with the square of its state and
  // its sampled states with its runs, not with a cone: on the generated
  // 32 x 32 program (1,047 state variables) 3,074,918 candidates, 15.2 GB
  // and past the time limit before Houdini began. Above the bound its
  // outputs go on alone, each with its own cone's candidates.
  if (whole && reduced.problem.ts->statevars().size() > kWholeProductStates) return out;
  // `whole`: every candidate of the product in two rounds, as one output's
  // cone gets them; else each cone's related candidates, sampled and mined
  // on each cone's variables alone.
  const Cones cones = whole ? Cones{} : cones_of(*reduced.problem.ts, goods);
  // For a group, a first pass of the seeded runs (not the acceptance
  // tests') finds a difference and which variables change: the others are
  // asked of a solver (cones.hpp, constant_states), which finds the same
  // constants from any superset of them. It keeps no state: the layers are
  // sampled on their own variables by every run (correspondence.hpp), and a
  // difference found there ends the group's proof as one found here does.
  const SamplingOptions so = at_rest(m);
  SamplingOptions first = so;
  first.trips.clear();
  first.max_states = 0;
  const Samples s = sample(reduced.problem, whole ? so : first);
  if (s.violation) return out;  // an output differs: each is decided alone, its run replayed
  const checker::Work work = o.work * static_cast<checker::Work>(qs.size());
  const Correspondence c = prove_by_correspondence(reduced.problem, s, o.limits.with_work(work), so, cones);
  if (c.result.verdict != checker::Verdict::Proved) {
    if (c.result.reason == checker::UnknownReason::TimeLimit) throw checker::Interrupted();
    return out;
  }
  checker::check::recheck_proof(checker::reducing(make), c.result, &o.limits);
  out.proved = true;
  out.k = c.result.k;
  return out;
}

// Everything the proofs depend on, as text.
std::string key_of(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou, const ResolvedMap& map,
                   const CheckOptions& o) {
  return std::string(to_string(o.relation)) + " " + std::to_string(o.work) + " " + formats::signature(m) + " " +
         pou.name + " " + std::to_string(map.scan_ms) + "\n" + formats::plc_map_json(map.map) + "\n" +
         plc::print_program(program);
}

// An answer found once by whichever asker comes first; the others wait for
// it. An asker that fails (interrupted) leaves it to the next one.
template <class T>
class Once {
 public:
  T get(const std::function<T()>& find) {
    std::promise<T> promise;
    std::shared_future<T> answer;
    bool mine = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!answer_.valid()) {
        answer_ = promise.get_future().share();
        mine = true;
      }
      answer = answer_;
    }
    if (mine) {
      try {
        promise.set_value(find());
      } catch (...) {
        {
          std::lock_guard<std::mutex> lock(mutex_);
          answer_ = {};
        }
        promise.set_exception(std::current_exception());
      }
    }
    return answer.get();
  }

 private:
  std::mutex mutex_;
  std::shared_future<T> answer_;
};

// What one matrix, program, map and options share: the groups, then each
// group's proof.
struct Shared {
  Once<Groups> groups;
  Once<SharedProof> whole;  // every output at once, every candidate of the product
  std::mutex mutex;
  std::map<std::size_t, std::shared_ptr<Once<SharedProof>>> proofs;  // by the group's first question
  std::shared_ptr<Once<SharedProof>> proof_of(std::size_t first) {
    std::lock_guard<std::mutex> lock(mutex);
    auto& p = proofs[first];
    if (!p) p = std::make_shared<Once<SharedProof>>();
    return p;
  }
};

// The last few runs' shares, by key.
class Memo {
 public:
  std::shared_ptr<Shared> get(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [k, s] : kept_)
      if (k == key) return s;
    kept_.emplace_back(key, std::make_shared<Shared>());
    if (kept_.size() > kKept) kept_.pop_front();
    return kept_.back().second;
  }

 private:
  static constexpr std::size_t kKept = 4;
  std::mutex mutex_;
  std::deque<std::pair<std::string, std::shared_ptr<Shared>>> kept_;
};

}  // namespace

SharedProof shared_proof(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                         const ResolvedMap& map, const CheckOptions& options, const OutputQuestion& q) {
  static Memo memo;
  const std::shared_ptr<Shared> shared = memo.get(key_of(m, program, pou, map, options));
  const std::vector<OutputQuestion> qs = questions(m, map);
  const Groups groups = shared->groups.get([&] {
    return qs.size() < 2 ? Groups{} : group_questions(m, program, pou, map, qs, options.relation);
  });
  for (const auto& g : groups) {
    const bool member = std::any_of(g.begin(), g.end(), [&](std::size_t i) {
      return qs[i].effect == q.effect && qs[i].position == q.position;
    });
    if (!member) continue;
    std::vector<OutputQuestion> group;
    for (std::size_t i : g) group.push_back(qs[i]);
    const SharedProof by_cones =
        shared->proof_of(g.front())->get([&] { return prove_group(m, program, pou, map, group, options); });
    if (by_cones.proved) return by_cones;
    break;
  }
  // The group's cones did not prove it: the whole product with every
  // candidate, which proves what cones cannot relate (random matrix 1036's
  // BDV_501A and BDV_501B, unknown when decided alone).
  return shared->whole.get([&] { return prove_group(m, program, pou, map, qs, options, true); });
}

namespace {

// The value of a cause's input that trips it: a discrete DTT input FALSE, an
// ETT input TRUE (6.3.4), an analog input one past its limit and hysteresis
// (6.3.5), as default_tag_value keeps it one short of them.
checker::Value tripping_value(const model::Cause& c, const model::CauseTag& t) {
  checker::Value v;
  if (c.input == model::InputKind::Analog && c.analog) {
    const double limit = c.analog->limit, hyst = c.analog->hysteresis;
    v.is_float = true;
    v.f = static_cast<float>(c.analog->limit_type == model::LimitType::High ? limit + hyst + 1.0 : limit - hyst - 1.0);
  } else {
    v.i = t.ett ? 1 : 0;
  }
  return v;
}

using Inputs = std::map<std::string, checker::Value>;

// The scans that cover `ms` on a scan of `scan` ms, and one more.
int scans(std::uint32_t ms, std::uint32_t scan) { return static_cast<int>((ms + scan - 1) / scan) + 1; }

// What trips an effect: the inputs of its causes (those of a processed
// intersection), each at its tripping value, and the scans their longest
// delay takes.
struct Tripping {
  Inputs inputs;
  std::uint32_t delay_ms = 0;
};

void add_cause(const model::InputTable& table, const model::Cause& c, Tripping& t) {
  if (c.function == model::CauseFunction::Comment) return;
  for (const auto& tag : c.tags)
    if (const auto i = table.find(tag.name)) t.inputs.emplace("input." + table.tags()[*i].name, tripping_value(c, tag));
  t.delay_ms = std::max(t.delay_ms, c.time.ms);
}

Tripping tripping(const model::Matrix& m, const model::InputTable& table, const model::Effect& e) {
  Tripping t;
  for (const model::Intersection* x : m.intersections_of_effect(e.id)) {
    const model::Cause* c = m.find_cause(x->cause);
    if (c && x->type != model::IntersectionType::X && x->type != model::IntersectionType::Note)
      add_cause(table, *c, t);
  }
  return t;
}

// What resets an effect or starts its override (O.2, O.3, E.1): its reset
// tag's rising edge, the tag itself or what it refers to (a cause, an
// effect) tripped; without a reset tag the operator's two commands. The
// scans a pulse lasts: the referred element's delays.
std::vector<Inputs> reset_pulses(const model::Matrix& m, const model::InputTable& table, const model::Effect& e,
                                 int& length) {
  const std::uint32_t scan = std::max<std::uint32_t>(m.cycle_ms, 1);
  length = 1;
  if (!e.reset_tag) {
    // The commands count only with secure write enabled (M.3).
    const std::string id = std::to_string(e.id);
    Inputs override_cmd{{"cmd.override_effect[" + id + "]", checker::Value{.i = 1}}};
    Inputs reset_cmd{{"cmd.reset_effect[" + id + "]", checker::Value{.i = 1}}};
    if (m.secure_write)
      if (const auto i = table.find(m.secure_write->enable_tag)) {
        const std::string enable = "input." + table.tags()[*i].name;
        override_cmd.emplace(enable, checker::Value{.i = 1});
        reset_cmd.emplace(enable, checker::Value{.i = 1});
      }
    return {override_cmd, reset_cmd};
  }
  Tripping t;
  const auto ref = model::parse_internal_ref(*e.reset_tag);
  if (!ref) {
    if (const auto i = table.find(*e.reset_tag)) t.inputs.emplace("input." + table.tags()[*i].name, checker::Value{.i = 1});
  } else if (ref->kind == model::InternalRef::Kind::Cause) {
    if (const model::Cause* c = m.find_cause(ref->id)) add_cause(table, *c, t);
  } else if (const model::Effect* x = m.find_effect(ref->id)) {
    t = tripping(m, table, *x);
    if (ref->kind == model::InternalRef::Kind::EffectTag) t.delay_ms += x->output_delay_ms;
  }
  if (t.inputs.empty()) return {};
  length = scans(t.delay_ms, scan);
  return {t.inputs};
}

// An effect's output tag follows its trip only while its process value is
// healthy (E.8, E.9: TRUE gives a DTT tag TRUE and an ETT tag FALSE when the
// effect is not active); at rest a BPCS tag is FALSE, so a pass-through
// ETT tag is TRUE and never rises. The process value an effect's reset tag
// `Effect[x][y]` needs held TRUE through the trip's run, if any.
Inputs healthy_source(const model::Matrix& m, const model::InputTable& table, const model::Effect& e) {
  if (!e.reset_tag) return {};
  const auto ref = model::parse_internal_ref(*e.reset_tag);
  if (!ref || ref->kind != model::InternalRef::Kind::EffectTag) return {};
  const model::Effect* x = m.find_effect(ref->id);
  if (!x || !x->process_data || !x->process_data->pass_through || !x->process_data->tag) return {};
  const auto i = table.find(*x->process_data->tag);
  if (!i) return {};
  return {{"input." + table.tags()[*i].name, checker::Value{.i = 1}}};
}

// For each effect, an acceptance test's run: its causes tripped together,
// held through their longest delay, the output delay and the override's
// longest time; its reset pulsed, tripped and released.
std::vector<SamplingOptions::Trip> trips_of(const model::Matrix& m) {
  std::vector<SamplingOptions::Trip> out;
  const std::uint32_t scan = std::max<std::uint32_t>(m.cycle_ms, 1);
  const model::InputTable table(m);
  for (const auto& e : m.effects) {
    if (e.function == model::EffectFunction::Comment) continue;
    Tripping t = tripping(m, table, e);
    if (t.inputs.empty()) continue;
    SamplingOptions::Trip trip;
    trip.inputs = std::move(t.inputs);
    const std::uint32_t override_ms = e.override_time ? e.override_time->max_s * 1000 : 0;
    trip.hold = scans(std::max(t.delay_ms + e.output_delay_ms, override_ms), scan) + 1;
    trip.pulses = reset_pulses(m, table, e, trip.pulse);
    trip.inputs.merge(healthy_source(m, table, e));  // a cause's own tripping value first
    out.push_back(std::move(trip));
  }
  return out;
}

}  // namespace

SamplingOptions at_rest(const model::Matrix& m) {
  auto rest = std::make_shared<std::map<std::string, checker::Value>>();
  const model::InputTable table(m);
  const model::CycleInput defaults = model::default_cycle_input(m);
  for (std::size_t i = 0; i < table.tags().size(); ++i) {
    checker::Value v;
    v.is_float = table.tags()[i].kind == model::TagKind::Analog;
    v.f = defaults.tags.at(i).value;
    v.i = v.is_float ? 0 : defaults.tags.at(i).value != 0.0f;
    (*rest)["input." + table.tags()[i].name] = v;
  }
  SamplingOptions o;
  o.trips = trips_of(m);
  o.rest = [rest](const std::string& name) -> std::optional<checker::Value> {
    const auto it = rest->find(name);
    if (it == rest->end()) return std::nullopt;
    return it->second;
  };
  return o;
}

}  // namespace cemv::plc_check
