// Completing a cemv-plc-map/1 against a matrix and a program (docs/plc.md
// "Map and relations").
#include "plc_check/map.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "formats/diagnostics.hpp"
#include "model/text.hpp"

namespace cemv::plc_check {

namespace {

using formats::LoadIssue;

const char* type_name(VarType t) {
  switch (t) {
    case VarType::Bool: return "BOOL";
    case VarType::Int: return "an integer";
    case VarType::Real: return "REAL";
    case VarType::Time: return "TIME";
    default: return "another type";
  }
}

bool readable_input(VarKind k) { return k == VarKind::Input || k == VarKind::InOut; }
bool writable_output(VarKind k) { return k == VarKind::Output || k == VarKind::InOut; }

// "A, B, C" with at most 20 names, then "... and N more".
std::string listing(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < 20; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > 20) s += ", ... and " + std::to_string(names.size() - 20) + " more";
  return s;
}

std::string value_text(double v) {
  std::string s = model::float_text(static_cast<float>(v));
  return s;
}

// The program's variables as the map looks them up: by the exact name, by
// name key, or as the map names them; each bound to one thing of the matrix.
class VariableFinder {
 public:
  VariableFinder(const ProgramInterface& p, std::vector<std::string>& problems) : p_(p), problems_(problems) {
    for (const auto& v : p.variables) by_key_[name_key(v.name)].push_back(&v);
  }

  const ProgramVariable* exact(const std::string& name) const {
    // IEC 61131-3 identifiers are not case-sensitive.
    for (const auto& v : p_.variables)
      if (model::tag_key(v.name) == model::tag_key(name)) return &v;
    return nullptr;
  }

  // The one variable whose key is `key` and that `fits`; nullptr when none,
  // or when several (then a problem says which).
  template <class Fits>
  const ProgramVariable* by_name(const std::string& key, const std::string& what, Fits&& fits) {
    auto it = by_key_.find(key);
    if (it == by_key_.end()) return nullptr;
    std::vector<const ProgramVariable*> hits;
    for (const auto* v : it->second)
      if (fits(*v)) hits.push_back(v);
    if (hits.size() > 1) {
      std::vector<std::string> names;
      for (const auto* v : hits) names.push_back(v->name);
      problems_.push_back(what + " matches several program variables by name (" + listing(names) +
                         "); name the one in the map");
      return nullptr;
    }
    return hits.empty() ? nullptr : hits.front();
  }

  // Checks a variable the map names: it exists, is of `type` and of a fitting kind.
  const ProgramVariable* named(const std::string& name, const std::string& what, VarType type, bool input) {
    const ProgramVariable* v = exact(name);
    if (!v) {
      problems_.push_back(what + ": the program has no variable " + model::in_quotes(name));
      return nullptr;
    }
    if (v->type != type) {
      problems_.push_back(what + ": " + v->name + " is " + type_name(v->type) + ", not " + type_name(type));
      return nullptr;
    }
    if (input ? !readable_input(v->kind) : !writable_output(v->kind)) {
      problems_.push_back(what + ": " + v->name + " is not a " + (input ? "VAR_INPUT" : "VAR_OUTPUT") +
                         " of " + p_.pou);
      return nullptr;
    }
    use(*v);
    return v;
  }

  // One variable carries one thing: a second binding is a contradiction.
  void use(const ProgramVariable& v) {
    if (!used_.insert(model::tag_key(v.name)).second)
      problems_.push_back("program variable " + v.name + " is bound to two things of the matrix");
  }

  bool is_used(const std::string& name) const { return used_.count(model::tag_key(name)) > 0; }

 private:
  const ProgramInterface& p_;
  std::vector<std::string>& problems_;
  std::map<std::string, std::vector<const ProgramVariable*>> by_key_;
  std::set<std::string> used_;
};

class Resolver {
 public:
  Resolver(const model::Matrix& m, const ProgramInterface& p, const formats::PlcMap* given)
      : m_(m), p_(p), given_(given), vars_(p, problems) {}

  ResolvedMap run() {
    out_.map.pou = p_.pou;
    scan_time();
    inputs();
    outputs();
    commands();
    program_inputs();
    return std::move(out_);
  }

  std::vector<std::string> problems;

 private:
  void scan_time() {
    if (given_ && given_->scan_ms) out_.scan_ms = *given_->scan_ms;
    else if (p_.task_ms) out_.scan_ms = *p_.task_ms;
    else {
      out_.scan_ms = m_.cycle_ms;
      out_.assumptions.push_back("scan time " + std::to_string(m_.cycle_ms) +
                                 " ms, the matrix's cycle (neither the map nor the program states one)");
    }
    out_.map.scan_ms = out_.scan_ms;
    if (out_.scan_ms != m_.cycle_ms)
      problems.push_back("scan time " + std::to_string(out_.scan_ms) + " ms differs from the matrix's cycle " +
                         std::to_string(m_.cycle_ms) + " ms; a scan-by-scan comparison needs the same time base");
  }

  const formats::PlcInputBinding* given_input(const std::string& tag) const {
    if (!given_) return nullptr;
    for (const auto& b : given_->inputs)
      if (model::tag_key(b.tag) == model::tag_key(tag)) return &b;
    return nullptr;
  }

  void inputs() {
    const model::InputTable table(m_);
    std::vector<std::string> missing;
    if (given_)
      for (const auto& b : given_->inputs)
        if (!table.find(b.tag)) problems.push_back("the matrix reads no input tag " + model::in_quotes(b.tag));
    for (const auto& tag : table.tags()) {
      const VarType type = tag.kind == model::TagKind::Analog ? VarType::Real : VarType::Bool;
      const bool cause_input =
          std::find(tag.roles.begin(), tag.roles.end(), model::TagRole::CauseInput) != tag.roles.end();
      formats::PlcInputBinding b;
      b.tag = tag.name;
      const auto* g = given_input(tag.name);
      if (g && !g->variable.empty()) {
        if (const auto* v = vars_.named(g->variable, "input tag " + tag.name, type, true)) b.variable = v->name;
      } else if (g) {
        b.value = g->value;
        out_.assumptions.push_back("input tag " + tag.name + " held at " + value_text(*g->value) +
                                   " with good quality (the map says so)");
      } else if (const auto* v = vars_.by_name(name_key(tag.name), "input tag " + tag.name,
                                               [&](const ProgramVariable& x) {
                                                 return readable_input(x.kind) && x.type == type;
                                               })) {
        vars_.use(*v);
        b.variable = v->name;
      } else {
        missing.push_back(tag.name);
      }
      if (!b.variable.empty()) quality(tag.name, cause_input, g, b);
      out_.map.inputs.push_back(std::move(b));
    }
    if (!missing.empty())
      problems.push_back("matrix input tags without a program variable (none of the same name, ignoring case, "
                         "'-' and '_', of the tag's type): " + listing(missing));
  }

  void quality(const std::string& tag, bool cause_input, const formats::PlcInputBinding* g,
               formats::PlcInputBinding& b) {
    if (g && (!g->bad_quality.empty() || g->good_quality) && !cause_input) {
      problems.push_back("input tag " + tag + ": only a cause input has a quality (docs/semantics.md I.2)");
      return;
    }
    if (!cause_input) return;
    if (g && !g->bad_quality.empty()) {
      if (const auto* v = vars_.named(g->bad_quality, "bad quality of " + tag, VarType::Bool, true))
        b.bad_quality = v->name;
      return;
    }
    if (g && g->good_quality) {
      b.good_quality = true;
      out_.assumptions.push_back("input tag " + tag + " of good quality (the map says so)");
      return;
    }
    for (const char* suffix : {"bq", "bad"}) {
      if (const auto* v = vars_.by_name(name_key(tag) + suffix, "bad quality of " + tag, [](const ProgramVariable& x) {
            return readable_input(x.kind) && x.type == VarType::Bool;
          })) {
        vars_.use(*v);
        b.bad_quality = v->name;
        return;
      }
    }
    b.good_quality = true;
    out_.assumptions.push_back("input tag " + tag + " of good quality (the program reads no " + tag + "_BQ)");
  }

  void outputs() {
    std::vector<std::string> missing;
    std::map<std::string, int> writers;  // tag key -> effects writing it
    for (const auto& e : m_.effects)
      if (e.function != model::EffectFunction::Comment)
        for (const auto& t : e.tags) ++writers[model::tag_key(t.name)];
    if (given_)
      for (const auto& b : given_->outputs)
        if (!writers.count(model::tag_key(b.tag))) problems.push_back("no effect writes output tag " + model::in_quotes(b.tag));
    for (const auto& e : m_.effects) {
      if (e.function == model::EffectFunction::Comment) continue;
      for (const auto& t : e.tags) {
        formats::PlcOutputBinding b;
        b.tag = t.name;
        if (writers[model::tag_key(t.name)] > 1) b.effect = e.id;
        const formats::PlcOutputBinding* g = nullptr;
        if (given_)
          for (const auto& x : given_->outputs)
            if (model::tag_key(x.tag) == model::tag_key(t.name) && (x.effect == 0 || x.effect == e.id)) g = &x;
        const std::string what = "output tag " + t.name + " of effect " + std::to_string(e.id);
        if (g) {
          if (const auto* v = vars_.named(g->variable, what, VarType::Bool, false)) b.variable = v->name;
        } else if (b.effect) {
          missing.push_back(t.name + " (effect " + std::to_string(e.id) + ": several effects write it, the map must say)");
        } else if (const auto* v = vars_.by_name(name_key(t.name), what, [](const ProgramVariable& x) {
                     return writable_output(x.kind) && x.type == VarType::Bool;
                   })) {
          vars_.use(*v);
          b.variable = v->name;
        } else {
          missing.push_back(t.name);
        }
        out_.map.outputs.push_back(std::move(b));
      }
    }
    if (!missing.empty())
      problems.push_back("matrix output tags without a BOOL VAR_OUTPUT of the program: " + listing(missing));
  }

  static bool covers(const formats::PlcCommandBinding& b, const model::Command& c) {
    return b.op == c.op && (!b.cause || b.cause == c.cause) && (!b.effect || b.effect == c.effect) &&
           (!b.tag || b.tag == c.tag) && (b.tag_name.empty() || model::tag_key(b.tag_name) == model::tag_key(c.tag_name)) &&
           (!b.on || *b.on == c.on);
  }

  void commands() {
    const auto slots = command_slots(m_);
    std::vector<bool> done(slots.size(), false);
    std::vector<std::string> missing;
    if (given_)
      for (const auto& b : given_->commands) given_command(b, slots, done);
    for (std::size_t i = 0; i < slots.size(); ++i) {
      if (done[i]) continue;
      const auto& s = slots[i];
      const ProgramVariable* v = nullptr;
      if (s.command.op != model::CommandOp::SimulateTag)
        v = vars_.by_name(name_key(s.default_name), s.label, [](const ProgramVariable& x) {
          return readable_input(x.kind) && x.type == VarType::Bool;
        });
      if (!v) {
        missing.push_back(s.label);
        continue;
      }
      vars_.use(*v);
      out_.map.commands.push_back(binding(s.command, v->name));
    }
    if (!missing.empty())
      problems.push_back("operator commands the matrix accepts without a program variable (map each to a BOOL "
                         "VAR_INPUT or declare it unused): " + listing(missing));
  }

  static formats::PlcCommandBinding binding(const model::Command& c, const std::string& variable) {
    formats::PlcCommandBinding b;
    b.op = c.op;
    b.cause = c.cause;
    b.effect = c.effect;
    b.tag = c.tag;
    b.tag_name = c.tag_name;
    if (c.op == model::CommandOp::SoftBypassCause || c.op == model::CommandOp::SoftBypassTag ||
        c.op == model::CommandOp::SoftBypassEffect)
      b.on = c.on;
    b.variable = variable;
    return b;
  }

  void given_command(const formats::PlcCommandBinding& b, const std::vector<CommandSlot>& slots,
                     std::vector<bool>& done) {
    std::vector<std::size_t> hits;
    for (std::size_t i = 0; i < slots.size(); ++i)
      if (!done[i] && covers(b, slots[i].command)) hits.push_back(i);
    const std::string what = std::string("command ") + model::to_string(b.op);
    if (hits.empty()) {
      problems.push_back(what + " in the map names no command the matrix accepts (or one mapped before)");
      return;
    }
    if (b.variable.empty()) {
      for (auto i : hits) done[i] = true;
      out_.map.commands.push_back(b);
      out_.assumptions.push_back(what + " never issued (declared unused): " + std::to_string(hits.size()) +
                                 (hits.size() == 1 ? " command, " : " commands, ") + slots[hits.front()].label +
                                 (hits.size() > 1 ? ", ..." : ""));
      return;
    }
    if (b.op == model::CommandOp::SimulateTag) {
      problems.push_back(what + ": a simulation carries a value; cemv-plc-map/1 can only declare it unused");
      return;
    }
    if (hits.size() > 1) {
      problems.push_back(what + " mapped to " + b.variable + " names " + std::to_string(hits.size()) +
                         " commands; give its cause, effect, tag and on");
      return;
    }
    if (!vars_.named(b.variable, slots[hits.front()].label, VarType::Bool, true)) return;
    done[hits.front()] = true;
    out_.map.commands.push_back(binding(slots[hits.front()].command, vars_.exact(b.variable)->name));
  }

  void program_inputs() {
    std::vector<std::string> missing;
    std::set<std::string> held;
    if (given_)
      for (const auto& b : given_->program_inputs) {
        const ProgramVariable* v = vars_.exact(b.variable);
        if (!v || !readable_input(v->kind)) {
          problems.push_back("program input " + model::in_quotes(b.variable) + " in the map is no VAR_INPUT of " + p_.pou);
          continue;
        }
        if (vars_.is_used(v->name)) {
          problems.push_back("program input " + v->name + " is bound to the matrix and held at a value");
          continue;
        }
        held.insert(model::tag_key(v->name));
        out_.map.program_inputs.push_back({v->name, b.value});
        out_.assumptions.push_back("program input " + v->name + " held at " + value_text(b.value) + " (the map says so)");
      }
    for (const auto& v : p_.variables)
      if (readable_input(v.kind) && !vars_.is_used(v.name) && !held.count(model::tag_key(v.name)))
        missing.push_back(v.name);
    if (!missing.empty())
      problems.push_back("program inputs without a matrix counterpart (bind them or hold them at a value in the "
                         "map's program_inputs): " + listing(missing));
  }

  const model::Matrix& m_;
  const ProgramInterface& p_;
  const formats::PlcMap* given_;
  VariableFinder vars_;
  ResolvedMap out_;
};

}  // namespace

std::string name_key(std::string_view name) {
  std::string key;
  for (char ch : name)
    if (ch != '_' && ch != '-') key += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return key;
}

ResolvedMap resolve_map(const model::Matrix& m, const ProgramInterface& program, const formats::PlcMap* given,
                        const std::string& map_source) {
  Resolver r(m, program, given);
  ResolvedMap out = r.run();
  if (given && !given->pou.empty() && model::tag_key(given->pou) != model::tag_key(program.pou))
    r.problems.insert(r.problems.begin(), "the map is for POU " + given->pou + ", the program checked is " + program.pou);
  if (!r.problems.empty()) {
    std::vector<LoadIssue> issues;
    const std::string file = given ? map_source : program.file;
    for (auto& p : r.problems) issues.push_back({"", std::move(p), file});
    throw formats::LoadError(std::move(issues));
  }
  return out;
}

}  // namespace cemv::plc_check
