// Validation of missing intersection configurations (11.5) and of simulation
// permissions (10.7.3.4).
#include "model/validate_checks.hpp"

#include <set>
#include <string>

#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::model::validation {

namespace {

class GraphChecks : public Checks {
 public:
  using Checks::Checks;

  void run() {
    connectivity();
    simulation();
  }

 private:
  // ---- missing intersection configurations (11.5) ----------------------------

  void connectivity() {
    std::set<int> cause_linked, effect_linked, cause_read;
    for (const auto& x : m_.intersections) {
      if (x.type == IntersectionType::Note) continue;
      const Cause* c = cause_by_id(x.cause);
      const Effect* e = effect_by_id(x.effect);
      if (!c || !e || !processed(*c) || !processed(*e)) continue;
      cause_linked.insert(x.cause);
      effect_linked.insert(x.effect);
    }
    for (const auto& r : internal_references(m_))
      if (r.source.kind == Node::Kind::Cause) cause_read.insert(r.source.id);
    auto matrix_read = [&](const std::string& tag) {
      if (auto ref = parse_internal_ref(tag); ref && ref->kind == InternalRef::Kind::Cause)
        cause_read.insert(ref->id);
    };
    if (m_.secure_write) matrix_read(m_.secure_write->enable_tag);
    if (m_.group_deactivation) {
      matrix_read(m_.group_deactivation->enable_tag);
      matrix_read(m_.group_deactivation->set_tag);
    }
    for (const auto& c : m_.causes)
      if (processed(c) && !cause_linked.count(c.id) && !cause_read.count(c.id))
        add("W-CAUSE-UNUSED", at(c),
            "the cause has no intersection with an effect and no internal reference reads it");
    for (const auto& e : m_.effects)
      if (processed(e) && !effect_linked.count(e.id))
        add("W-EFFECT-UNDRIVEN", at(e), "no cause is linked to the effect: it never trips");
  }

  // ---- maintenance permissions (10.7.3.4) --------------------------------------

  // The format lets every tag be simulated unless the matrix says otherwise;
  // a matrix that restricts none was most likely never asked the question.
  void simulation() {
    std::size_t tags = 0;
    for (const auto& c : m_.causes) {
      if (!processed(c)) continue;
      for (const auto& t : c.tags) {
        if (parse_internal_ref(t.name)) continue;
        if (!t.simulation_allowed) return;
        ++tags;
      }
    }
    for (const auto& e : m_.effects) {
      if (!processed(e)) continue;
      for (const auto& t : e.tags) {
        if (!t.simulation_allowed) return;
        ++tags;
      }
    }
    if (tags == 0) return;
    add("W-SIMULATION-UNRESTRICTED", at_matrix(),
        "all " + std::to_string(tags) + " cause input and output tags may be simulated (no tag has "
        "simulation_allowed false)" + (m_.secure_write ? "" : " and no secure write gates the command") +
        ": a simulated tag overrides the plant; restrict simulation to the tags that need it");
  }
};

}  // namespace

void check_graph(const Matrix& m, std::vector<Finding>& out) { GraphChecks(m, out).run(); }

}  // namespace cemv::model::validation
