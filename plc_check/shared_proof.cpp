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
  // A first pass finds a difference and the variables that never change
  // (cones.hpp, constant_states); the layers are sampled again on their own
  // variables (correspondence.hpp). The first keeps one state of each cone.
  const SamplingOptions so = at_rest(m);
  SamplingOptions first = so;
  first.cones = cones;
  first.max_states = 1;
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
  o.rest = [rest](const std::string& name) -> std::optional<checker::Value> {
    const auto it = rest->find(name);
    if (it == rest->end()) return std::nullopt;
    return it->second;
  };
  return o;
}

}  // namespace cemv::plc_check
