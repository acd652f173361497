// Validation of the external tags a matrix uses and of its internal references.
#include "model/validate_checks.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::model::validation {

namespace {

// One use of an external tag by the matrix.
enum class Use { AnalogInput, DiscreteInput, Control, Output, MatrixControl };
struct TagUse {
  Use use;
  Where where;       // the element (or the matrix)
  std::string what;  // "input tag 2", "bypass_tag", "output tag 1", "secure_write.enable_tag"
  std::string name;  // as written
  int owner = 0;     // element id (0 for the matrix)
};

class TagChecks : public Checks {
 public:
  using Checks::Checks;

  void run() {
    tags();
    references();
  }

 private:
  // ---- external tags ---------------------------------------------------------

  void tags() {
    std::map<std::string, std::vector<TagUse>> uses;
    auto use = [&](const std::optional<std::string>& name, Use kind, const Where& where,
                   std::string what, int owner) {
      if (!name || name->empty() || parse_internal_ref(*name)) return;
      uses[tag_key(*name)].push_back({kind, where, std::move(what), *name, owner});
    };
    if (m_.secure_write)
      use(m_.secure_write->enable_tag, Use::MatrixControl, at_matrix(), "secure_write.enable_tag",
          0);
    if (m_.group_deactivation) {
      use(m_.group_deactivation->enable_tag, Use::MatrixControl, at_matrix(),
          "group_deactivation.enable_tag", 0);
      use(m_.group_deactivation->set_tag, Use::MatrixControl, at_matrix(),
          "group_deactivation.set_tag", 0);
    }
    for (const auto& c : m_.causes) {
      if (!processed(c)) continue;
      for (std::size_t i = 0; i < c.tags.size(); ++i)
        use(c.tags[i].name, c.input == InputKind::Analog ? Use::AnalogInput : Use::DiscreteInput,
            at(c), "input tag " + std::to_string(i + 1), c.id);
      use(c.bypass_tag, Use::Control, at(c), "bypass_tag", c.id);
      use(c.inhibit_tag, Use::Control, at(c), "inhibit_tag", c.id);
    }
    for (const auto& e : m_.effects) {
      if (!processed(e)) continue;
      for (std::size_t i = 0; i < e.tags.size(); ++i) {
        if (parse_internal_ref(e.tags[i].name))
          add("E-OUTPUT-TAG-REFERENCE", at(e),
              "output tag " + std::to_string(i + 1) + " " + in_quotes(e.tags[i].name) +
                  " is an internal reference: references can only be read");
        use(e.tags[i].name, Use::Output, at(e), "output tag " + std::to_string(i + 1), e.id);
      }
      use(e.bypass_tag, Use::Control, at(e), "bypass_tag", e.id);
      use(e.reset_tag, Use::Control, at(e), "reset_tag", e.id);
      if (e.process_data) {
        use(e.process_data->tag, Use::Control, at(e), "process_data.tag", e.id);
        use(e.process_data->mask_tag, Use::Control, at(e), "process_data.mask_tag", e.id);
      }
    }

    auto describe = [](const TagUse& u) { return u.where.text + " (" + u.what + ")"; };
    for (const auto& [key, list] : uses) {
      const std::string& name = list.front().name;
      // Outputs: one writer per tag (11.5), never read by the matrix itself.
      std::vector<const TagUse*> outputs, readers, inputs, matrix_controls, others, analog,
          boolean;
      for (const auto& u : list) {
        (u.use == Use::Output ? outputs : readers).push_back(&u);
        if (u.use == Use::AnalogInput || u.use == Use::DiscreteInput) inputs.push_back(&u);
        (u.use == Use::MatrixControl ? matrix_controls : others).push_back(&u);
        if (u.use == Use::AnalogInput) analog.push_back(&u);
        if (u.use == Use::DiscreteInput || u.use == Use::Control || u.use == Use::MatrixControl)
          boolean.push_back(&u);
      }
      for (std::size_t i = 1; i < outputs.size(); ++i) {
        const TagUse* first = outputs.front();
        if (outputs[i]->owner == first->owner)
          add("E-OUTPUT-TAG-REPEATED", outputs[i]->where,
              outputs[i]->what + " " + in_quotes(outputs[i]->name) + " repeats " + first->what);
        else
          add("E-OUTPUT-TAG-SHARED", outputs[i]->where,
              outputs[i]->what + " " + in_quotes(outputs[i]->name) + " is also written by " +
                  describe(*first));
      }
      if (!outputs.empty() && !readers.empty()) {
        std::string list_text;
        for (const auto* r : readers) list_text += (list_text.empty() ? "" : ", ") + describe(*r);
        add("E-TAG-IN-AND-OUT", outputs.front()->where,
            outputs.front()->what + " " + in_quotes(name) + " is also read by " + list_text +
                " (use an internal reference Effect[x] or Effect[x][y] to read an effect)");
      }
      for (std::size_t i = 1; i < inputs.size(); ++i) {
        const TagUse* prev = inputs[i - 1];
        if (inputs[i]->owner == prev->owner)
          add("W-INPUT-TAG-REPEATED", inputs[i]->where,
              inputs[i]->what + " " + in_quotes(inputs[i]->name) + " repeats " + prev->what +
                  ": the voting counts one sensor twice");
        else
          add("W-INPUT-TAG-SHARED", inputs[i]->where,
              inputs[i]->what + " " + in_quotes(inputs[i]->name) + " is also read by " +
                  describe(*inputs.front()));
      }
      if (!analog.empty() && !boolean.empty())
        add("E-TAG-KIND-CONFLICT", analog.front()->where,
            analog.front()->what + " " + in_quotes(name) + " is analog (REAL) but " +
                describe(*boolean.front()) + " reads it as a Boolean");
      if (!matrix_controls.empty() && !others.empty()) {
        std::string list_text;
        for (const auto* o : others) list_text += (list_text.empty() ? "" : ", ") + describe(*o);
        add("E-CONTROL-TAG-COLLISION", at_matrix(),
            matrix_controls.front()->what + " " + in_quotes(name) + " is also used by " + list_text);
      }
    }
  }

  // ---- internal references ---------------------------------------------------

  // A reference must name an existing element (and output tag); naming a
  // comment-only element is legal but constant.
  void check_reference(const Where& where, const std::string& field, const std::string& tag,
                       const Node& source, int source_tag) {
    std::string prefix = field + " " + in_quotes(tag) + ": ";
    if (source.kind == Node::Kind::Cause) {
      const Cause* c = cause_by_id(source.id);
      if (!c) {
        add("E-REF-MISSING", where, prefix + "cause " + std::to_string(source.id) + " does not exist");
      } else if (!processed(*c)) {
        add("W-REF-COMMENT", where,
            prefix + cause_label(*c) + " is comment-only: the reference is always FALSE");
      }
      return;
    }
    const Effect* e = effect_by_id(source.id);
    if (!e) {
      add("E-REF-MISSING", where, prefix + "effect " + std::to_string(source.id) + " does not exist");
    } else if (!processed(*e)) {
      add("W-REF-COMMENT", where,
          prefix + effect_label(*e) + " is comment-only: the reference never changes");
    } else if (source_tag != 0 &&
               (source_tag < 1 || source_tag > static_cast<int>(e->tags.size()))) {
      add("E-REF-MISSING", where,
          prefix + effect_label(*e) + " has " + std::to_string(e->tags.size()) +
              " output tags, there is no tag " + std::to_string(source_tag));
    }
  }

  void references() {
    for (const auto& r : internal_references(m_)) {
      Where where = at(r.reader);
      if (r.reader.kind == Node::Kind::Cause) {
        if (const Cause* c = cause_by_id(r.reader.id)) where = at(*c);
      } else if (const Effect* e = effect_by_id(r.reader.id)) {
        where = at(*e);
      }
      check_reference(where, r.field, r.tag, r.source, r.source_tag);
      if (r.reader.kind == Node::Kind::Cause && r.field.starts_with("input tag")) {
        const Cause* c = cause_by_id(r.reader.id);
        if (c && c->input == InputKind::Analog)
          add("E-REF-ANALOG", where,
              r.field + " " + in_quotes(r.tag) +
                  " is an internal reference (Boolean) but the cause's input is analog");
      }
    }
    // Matrix-level control tags may be internal references too.
    auto matrix_ref = [&](const std::string& field, const std::string& tag) {
      auto ref = parse_internal_ref(tag);
      if (!ref) return;
      Node source{ref->kind == InternalRef::Kind::Cause ? Node::Kind::Cause : Node::Kind::Effect,
                  ref->id};
      check_reference(at_matrix(), field, tag, source,
                      ref->kind == InternalRef::Kind::EffectTag ? ref->tag : 0);
    };
    if (m_.secure_write) matrix_ref("secure_write.enable_tag", m_.secure_write->enable_tag);
    if (m_.group_deactivation) {
      matrix_ref("group_deactivation.enable_tag", m_.group_deactivation->enable_tag);
      matrix_ref("group_deactivation.set_tag", m_.group_deactivation->set_tag);
    }

    // Cycles (8.3): the run sequence follows the data flow, which a cycle cannot;
    // the graph breaks each cycle and the reader sees the previous cycle's value.
    DependencyGraph graph(m_);
    auto cycles = graph.cycles();
    for (const auto& cycle : cycles) {
      std::string text, stale;
      for (std::size_t i = 0; i < cycle.size(); ++i) {
        const Node& from = cycle[i];
        const Node& to = cycle[(i + 1) % cycle.size()];
        text += to_string(from) + " -> ";
        if (graph.reads_previous(from, to))
          stale += (stale.empty() ? "" : "; ") + to_string(to) + " reads " + to_string(from) +
                   " from the previous scan cycle";
      }
      text += to_string(cycle.front());
      Where where = at(cycle.front());
      if (cycle.front().kind == Node::Kind::Cause) {
        if (const Cause* c = cause_by_id(cycle.front().id)) where = at(*c);
      } else if (const Effect* e = effect_by_id(cycle.front().id)) {
        where = at(*e);
      }
      add("W-REF-CYCLE", where, "cycle " + text + (stale.empty() ? "" : ": " + stale));
    }
    if (cycles.size() >= kMaxReportedCycles)
      add("W-REF-CYCLE", at_matrix(),
          "at least " + std::to_string(kMaxReportedCycles) +
              " cycles through internal references; only the first " +
              std::to_string(kMaxReportedCycles) + " are listed");
  }
};

}  // namespace

void check_tags(const Matrix& m, std::vector<Finding>& out) { TagChecks(m, out).run(); }

}  // namespace cemv::model::validation
