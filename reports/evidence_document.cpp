#include "reports/evidence_document.hpp"

#include <map>
#include <regex>

#include "reports/check_report.hpp"

namespace cemv::reports::evidence_detail {

namespace {

using checker::PropertyResult;
using checker::PropertyVerdict;

// "intersection[3,2]" -> (3, 2).
bool support_cell(const std::string& key, Cell2& out) {
  static const std::regex re(R"(intersection\[(\d+),(\d+)\])");
  std::smatch mt;
  if (!std::regex_match(key, mt, re)) return false;
  out = {std::stoi(mt[1].str()), std::stoi(mt[2].str())};
  return true;
}

// The cells a trace runs through: intersections between the causes that
// became active in it and the effects the property reads.
std::set<Cell2> trace_cells(const model::Matrix& m, const PropertyResult& p) {
  std::set<Cell2> cells;
  if (!p.trace || p.trace->observables.empty()) return cells;
  const auto all = model::observables(m);
  std::set<int> causes, effects;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].kind != model::Node::Kind::Cause || all[i].field != "active") continue;
    for (const auto& snap : p.trace->observables)
      if (i < snap.size() && snap[i]) causes.insert(all[i].id);
  }
  for (const auto& key : property_elements(p))
    if (key.rfind("effect[", 0) == 0) effects.insert(std::stoi(key.substr(7)));
  for (const auto& x : m.intersections)
    if (model::is_processed(x.type) && causes.count(x.cause) && effects.count(x.effect)) cells.insert({x.cause, x.effect});
  return cells;
}

// The element a standard property is about: its effect when it names one.
std::string standard_element(const std::string& name) {
  static const std::regex effect(R"(\.e(\d+)(\.|$))"), cause(R"(\.c(\d+)(\.|$))");
  std::smatch mt;
  if (std::regex_search(name, mt, effect)) return "effect[" + mt[1].str() + "]";
  if (std::regex_search(name, mt, cause)) return "cause[" + mt[1].str() + "]";
  return "matrix";
}

std::string element_label(const model::Matrix& m, const std::string& key) {
  if (key.rfind("effect[", 0) == 0) {
    int id = std::stoi(key.substr(7));
    const auto* e = m.find_effect(id);
    return "effect " + std::to_string(id) + (e ? " " + e->name : "");
  }
  if (key.rfind("cause[", 0) == 0) {
    int id = std::stoi(key.substr(6));
    const auto* c = m.find_cause(id);
    return "cause " + std::to_string(id) + (c ? " " + c->name : "");
  }
  return key;
}

void add_limitations(Document& d) {
  const auto& prov = d.m.provenance;
  for (const auto& rec : prov.parameters) {
    for (const auto& f : rec.footnotes)
      if (!f.not_modelled.empty())
        d.limitations.push_back({"footnote not modelled", f.mark + " " + f.text + ": " + f.not_modelled, rec.file});
    for (const auto& l : rec.limitations) d.limitations.push_back({"stated limitation", l, rec.file});
    for (const auto& v : rec.values)
      d.limitations.push_back({"value supplied", v.element + " " + v.field + " = " + v.value +
                                                     (v.origin.empty() ? "" : " (" + v.origin + ")"),
                               rec.file});
  }
  for (const auto& rec : prov.imports)
    for (const auto& def : rec.defaults) d.limitations.push_back({"default adopted", def, rec.file});
  for (const auto& f : d.in.property_files)
    for (const auto& a : f.assumptions)
      d.limitations.push_back({"assumed away", a + " (every property of the file)", f.file});
  for (const auto& r : d.requirements) {
    if (!r.text) continue;
    for (const auto& a : r.text->assumptions)
      if (a.find("(every property of the file)") == std::string::npos)
        d.limitations.push_back({"assumed away", a + " (" + r.result->name + ")", r.result->file});
  }
}

void conclude(Document& d) {
  auto verdict_list = [&](const std::array<int, 6>& c) {
    std::string s;
    for (std::size_t v = 0; v < c.size(); ++v)
      if (c[v]) s += (s.empty() ? "" : ", ") + std::to_string(c[v]) + " " + verdict_name(static_cast<PropertyVerdict>(v));
    return s.empty() ? std::string("none") : s;
  };
  const std::string sig = d.in.check.matrix_signature;
  if (!d.valid) {
    d.conclusion.push_back("The matrix has " + std::to_string(d.errors) +
                           " validation errors (chapter Validation): it cannot be executed or encoded, so no "
                           "property was checked and nothing is proved about it.");
    d.conclusion.push_back("Not acceptable as it stands: fix the validation errors and produce the evidence again.");
    return;
  }
  const int unknown = d.counts[static_cast<int>(PropertyVerdict::Unknown)];
  const std::size_t total = d.in.check.properties.size();
  if (total == 0) {
    d.conclusion.push_back("No property was given: this report documents the matrix, its validation and its "
                           "provenance, and proves nothing about its behaviour.");
  } else {
    d.conclusion.push_back(std::to_string(total) + (total == 1 ? " property" : " properties") +
                           " checked: " + verdict_list(d.counts) + ".");
    d.conclusion.push_back(unknown == 0 ? "No property is unknown: every one was decided, and every answer was "
                                          "checked independently (counterexamples replayed on the reference "
                                          "runtime, proofs re-checked by a fresh solver)."
                                        : std::to_string(unknown) + " properties are unknown (not decided within "
                                                                    "the time limit): nothing is claimed for them.");
    if (!d.requirements.empty()) {
      if (d.requirements_not_passed.empty())
        d.conclusion.push_back("Every one of the " + std::to_string(d.requirements.size()) +
                               " requirements is proved (or, for a reachability requirement, witnessed).");
      else {
        std::string list;
        for (const auto& r : d.requirements_not_passed) list += (list.empty() ? "" : "; ") + r;
        d.conclusion.push_back(std::to_string(d.requirements_not_passed.size()) + " of the " +
                               std::to_string(d.requirements.size()) + " requirements " +
                               (d.requirements_not_passed.size() == 1 ? "is" : "are") + " not proved: " + list +
                               ". Each is explained in its section of chapter 1.");
      }
    }
    if (!d.standard.empty()) {
      std::vector<std::string> bad;
      for (const auto* p : d.standard)
        if (!passed(p->verdict)) bad.push_back(p->name + " (" + verdict_name(p->verdict) + ")");
      std::string list;
      for (std::size_t i = 0; i < bad.size() && i < 10; ++i) list += (i ? "; " : "") + bad[i];
      if (bad.size() > 10) list += "; and " + std::to_string(bad.size() - 10) + " more";
      d.conclusion.push_back(bad.empty() ? "Every property of the standard set holds."
                             : bad.size() == 1 ? "One property of the standard set does not hold: " + list +
                                                     " (chapter 2, Appendix A)."
                                               : std::to_string(bad.size()) +
                                                     " properties of the standard set do not hold: " + list +
                                                     " (chapter 2, Appendix A).");
    }
  }
  if (d.in.plc) {
    int related = 0, differs = 0;
    for (const auto& o : d.in.plc->outputs) related += o.verdict == "related", differs += o.verdict == "differs";
    const auto total = d.in.plc->outputs.size();
    d.conclusion.push_back(
        "PLC program " + d.in.plc->pou + " (SHA-256 " + d.in.plc->sha256 + "): " + std::to_string(related) + " of " +
        std::to_string(total) + " output tags proved " + d.in.plc->relation +
        (differs ? ", " + std::to_string(differs) + " differ (each run replayed on both sides)" : std::string()) +
        (total - related - differs ? ", " + std::to_string(total - related - differs) + " unknown" : std::string()) +
        ", under the assumptions listed (chapter The PLC program).");
  }
  if (d.warnings) d.conclusion.push_back("Validation reports " + std::to_string(d.warnings) +
                                         (d.warnings == 1 ? " warning" : " warnings") +
                                         " (no errors); each is listed and should be read.");
  if (!d.limitations.empty())
    d.conclusion.push_back("The statements hold for the model as described, within the " +
                           std::to_string(d.limitations.size()) + " limitations listed (chapter Limitations).");
  d.conclusion.push_back("They hold for the matrix with signature " + sig + " and no other version.");
}

}  // namespace

bool passed(checker::PropertyVerdict v) { return v == PropertyVerdict::Proved || v == PropertyVerdict::Reachable; }

std::string formal_text(const PropertyText& t) {
  std::string s = t.statement;
  for (const auto& a : t.assumptions) s += "\n" + a;
  return s;
}

Document build_document(const model::Matrix& m, const EvidenceInputs& in) {
  Document d(m, in);
  for (const auto& v : in.validation) (v.severity == model::Severity::Error ? d.errors : d.warnings)++;
  d.valid = d.errors == 0;
  std::map<std::pair<std::string, std::string>, const PropertyText*> texts;
  for (const auto& t : in.texts) texts[{t.file, t.name}] = &t;
  std::map<std::string, std::string> sha;
  for (const auto& f : in.property_files) sha[f.file] = f.sha256;
  std::map<std::string, ElementSummary> by_element;
  std::vector<std::string> element_order;
  for (const auto& p : in.check.properties) {
    d.counts[static_cast<int>(p.verdict)]++;
    if (p.line == 0) {  // the standard set: generated, no place in a file
      d.standard.push_back(&p);
      const std::string key = standard_element(p.name);
      auto [it, fresh] = by_element.emplace(key, ElementSummary{key, element_label(m, key), {}, {}});
      if (fresh) element_order.push_back(key);
      it->second.verdicts[static_cast<int>(p.verdict)]++;
      it->second.properties.push_back(&p);
      continue;
    }
    Requirement r;
    r.result = &p;
    if (auto t = texts.find({p.file, p.name}); t != texts.end()) r.text = t->second;
    r.file_sha256 = sha.count(p.file) ? sha[p.file] : "";
    Cell2 c;
    for (const auto& s : p.support)
      if (support_cell(s.key, c)) r.support_cells.insert(c);
    r.trace_cells = trace_cells(m, p);
    if (p.verdict == PropertyVerdict::Proved) d.support_cells.insert(r.support_cells.begin(), r.support_cells.end());
    d.trace_cells.insert(r.trace_cells.begin(), r.trace_cells.end());
    d.requirement_counts[static_cast<int>(p.verdict)]++;
    if (!passed(p.verdict)) d.requirements_not_passed.push_back(p.name + " (" + verdict_name(p.verdict) + ")");
    d.requirements.push_back(std::move(r));
  }
  // Elements in the matrix's order: causes by id, then effects by id.
  std::vector<std::string> keys;
  for (const auto& c : m.causes) keys.push_back("cause[" + std::to_string(c.id) + "]");
  for (const auto& e : m.effects) keys.push_back("effect[" + std::to_string(e.id) + "]");
  keys.push_back("matrix");
  for (const auto& k : keys)
    if (auto it = by_element.find(k); it != by_element.end()) d.standard_by_element.push_back(it->second);
  add_limitations(d);
  conclude(d);
  return d;
}

}  // namespace cemv::reports::evidence_detail
