// The correspondence of the whole product, found once (shared_proof.hpp).
#include "plc_check/shared_proof.hpp"

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
#include "plc_check/correspondence.hpp"

namespace cemv::plc_check {

namespace {

SharedProof prove_all(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                      const ResolvedMap& map, const CheckOptions& o) {
  SharedProof out;
  const std::vector<OutputQuestion> qs = questions(m, map);
  if (qs.size() < 2) return out;  // one output: its own decision is the same product
  const checker::ProblemFactory make = product_factory(m, program, pou, map, qs, o.relation);
  z3::context ctx;
  const checker::OwnedProblem reduced = checker::reduce(make(ctx));
  const SamplingOptions so = at_rest(m);
  const Samples s = sample(reduced.problem, so);
  if (s.violation) return out;  // an output differs: each is decided alone, its run replayed
  const checker::Work work = o.work * static_cast<checker::Work>(qs.size());
  const Correspondence c = prove_by_correspondence(reduced.problem, s, o.limits.with_work(work), so);
  if (c.result.verdict != checker::Verdict::Proved) {
    if (c.result.reason == checker::UnknownReason::TimeLimit) throw checker::Interrupted();
    return out;
  }
  checker::check::recheck_proof(checker::reducing(make), c.result, &o.limits);
  out.proved = true;
  out.k = c.result.k;
  return out;
}

// Everything the shared proof depends on, as text.
std::string key_of(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou, const ResolvedMap& map,
                   const CheckOptions& o) {
  return std::string(to_string(o.relation)) + " " + std::to_string(o.work) + " " + formats::signature(m) + " " +
         pou.name + " " + std::to_string(map.scan_ms) + "\n" + formats::plc_map_json(map.map) + "\n" +
         plc::print_program(program);
}

class Memo {
 public:
  SharedProof get(const std::string& key, const std::function<SharedProof()>& prove) {
    std::promise<SharedProof> promise;
    std::shared_future<SharedProof> answer;
    bool mine = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto it = answers_.find(key);
      if (it != answers_.end()) {
        answer = it->second;
      } else {
        answer = promise.get_future().share();
        answers_.emplace(key, answer);
        order_.push_back(key);
        if (order_.size() > kKept) {
          answers_.erase(order_.front());
          order_.pop_front();
        }
        mine = true;
      }
    }
    if (mine) {
      try {
        promise.set_value(prove());
      } catch (...) {
        forget(key);  // interrupted or failed: the next output tries again
        promise.set_exception(std::current_exception());
      }
    }
    return answer.get();
  }

 private:
  static constexpr std::size_t kKept = 4;
  void forget(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    answers_.erase(key);
    for (auto it = order_.begin(); it != order_.end(); ++it)
      if (*it == key) {
        order_.erase(it);
        break;
      }
  }
  std::mutex mutex_;
  std::map<std::string, std::shared_future<SharedProof>> answers_;
  std::deque<std::string> order_;
};

}  // namespace

SharedProof shared_proof(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                         const ResolvedMap& map, const CheckOptions& options) {
  static Memo memo;
  return memo.get(key_of(m, program, pou, map, options), [&] { return prove_all(m, program, pou, map, options); });
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
