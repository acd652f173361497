#include "reports/vcd.hpp"

#include <cctype>
#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

#include "model/vocabulary.hpp"

namespace cemv::reports {

namespace {

// Identifier codes: printable ASCII 33..126 in base 94, as 1364 allows.
std::string code(std::size_t n) {
  std::string s;
  do {
    s += static_cast<char>(33 + n % 94);
    n /= 94;
  } while (n);
  return s;
}

// VCD names are single words; keep letters, digits and _ (brackets would read
// as bit selects in viewers).
std::string word(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '_';
  return out.empty() ? "_" : out;
}

enum class VarKind { Wire, Integer, Real };

struct Var {
  VarKind kind;
  std::string code;
  std::vector<std::string> values;  // per cycle, already in VCD value syntax (without the code)
};

std::string bits(long v, int width) {
  std::string s;
  for (int b = width - 1; b >= 0; --b) s += ((v >> b) & 1) ? '1' : '0';
  auto first = s.find('1');
  return "b" + (first == std::string::npos ? std::string("0") : s.substr(first));
}

std::string real_text(float v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "r%.9g", static_cast<double>(v));
  return buf;
}

std::string value_line(const Var& v, const std::string& value) {
  return v.kind == VarKind::Wire ? value + v.code : value + " " + v.code;
}

}  // namespace

namespace {

// The declarations and values of the runs, one after another in `defs`.
class Dump {
 public:
  explicit Dump(const model::Matrix& m) : m_(m), table_(m), obs_(model::observables(m)) {}

  // The scopes `inputs`, `operator` and one per cause and effect of one run.
  void run(const checker::ConcreteTrace& t) {
    const std::size_t n = t.inputs.size();
    cycles_ = std::max(cycles_, n);
    defs_ << "$scope module inputs $end\n";
    std::vector<std::string> tag_code(table_.size());
    std::vector<bool> analog(table_.size());
    for (std::size_t i = 0; i < table_.size(); ++i) {
      const auto& tag = table_.tags()[i];
      analog[i] = tag.kind == model::TagKind::Analog;
      std::vector<std::string> values, bad;
      bool any_bad = false;
      for (std::size_t k = 0; k < n; ++k) {
        const auto& v = t.inputs[k].tags[i];
        values.push_back(analog[i] ? real_text(v.value) : (v.value != 0.0f ? "1" : "0"));
        bad.push_back(v.bad_quality ? "1" : "0");
        any_bad |= v.bad_quality;
      }
      tag_code[i] = decl(analog[i] ? VarKind::Real : VarKind::Wire, tag.name, std::move(values));
      if (any_bad) decl(VarKind::Wire, tag.name + "_bad", std::move(bad));
    }
    defs_ << "$upscope $end\n$scope module operator $end\n";
    {
      std::vector<std::string> count;
      for (std::size_t k = 0; k < n; ++k) count.push_back(bits(static_cast<long>(t.inputs[k].commands.size()), 32));
      decl(VarKind::Integer, "commands", std::move(count));
    }
    defs_ << "$upscope $end\n";

    std::string open;  // the element whose scope is open ("cause[3]")
    for (std::size_t i = 0; i < obs_.size(); ++i) {
      const auto& o = obs_[i];
      std::string element = o.key.substr(0, o.key.find('.'));
      if (element != open) {
        if (!open.empty()) defs_ << "$upscope $end\n";
        open = element;
        bool cause = o.kind == model::Node::Kind::Cause;
        std::string name = cause ? m_.find_cause(o.id)->name : m_.find_effect(o.id)->name;
        defs_ << "$scope module " << (cause ? "cause_" : "effect_") << o.id << "_" << word(name) << " $end\n";
        if (cause)  // the cause's input tags, aliased (same code as in `inputs`)
          for (const auto& ct : m_.find_cause(o.id)->tags)
            if (auto idx = table_.find(ct.name))
              defs_ << "$var " << (analog[*idx] ? "real 64 " : "wire 1 ") << tag_code[*idx] << " in_" << word(ct.name)
                    << " $end\n";
      }
      std::vector<std::string> values;
      for (std::size_t k = 0; k < n; ++k) {
        int v = t.observables[k][i];
        values.push_back(o.type == model::FieldType::Bool ? (v ? "1" : "0") : bits(v, 32));
      }
      std::string name = o.field;
      if (o.field == "tag") name = "out_" + m_.find_effect(o.id)->tags[static_cast<std::size_t>(o.tag - 1)].name;
      decl(o.type == model::FieldType::Bool ? VarKind::Wire : VarKind::Integer, name, std::move(values));
    }
    if (!open.empty()) defs_ << "$upscope $end\n";
  }

  std::ostringstream& defs() { return defs_; }

  // Header, definitions and the value changes. A run shorter than the
  // longest keeps its last values (VCD holds a value until it changes).
  std::string text(const VcdHeader& h, const std::string& what) const {
    std::ostringstream out;
    if (!h.date.empty()) out << "$date " << h.date << " $end\n";
    out << "$version cemv " << h.version << " $end\n";
    out << "$comment matrix " << m_.name << ", cycle " << m_.cycle_ms << " ms, " << what;
    if (!h.comment.empty()) out << "; " << h.comment;
    out << "; voting codes:";
    for (int v = 0; v <= static_cast<int>(model::Voting::Bypass); ++v)
      out << " " << v << "=" << model::to_string(static_cast<model::Voting>(v));
    out << " $end\n$timescale 1 ms $end\n" << defs_.str() << "$enddefinitions $end\n";
    for (std::size_t k = 0; k < cycles_; ++k) {
      out << "#" << static_cast<std::uint64_t>(k) * m_.cycle_ms << "\n";
      if (k == 0) out << "$dumpvars\n";
      for (const auto& v : vars_)
        if (k < v.values.size() && (k == 0 || v.values[k] != v.values[k - 1]))
          out << value_line(v, v.values[k]) << "\n";
      if (k == 0) out << "$end\n";
    }
    // The end of the last cycle, so viewers draw it full width.
    out << "#" << static_cast<std::uint64_t>(cycles_) * m_.cycle_ms << "\n";
    return out.str();
  }

 private:
  std::string decl(VarKind k, const std::string& name, std::vector<std::string> values) {
    Var v{k, code(vars_.size()), std::move(values)};
    const char* type = k == VarKind::Wire ? "wire 1" : k == VarKind::Integer ? "integer 32" : "real 64";
    defs_ << "$var " << type << " " << v.code << " " << word(name) << " $end\n";
    vars_.push_back(std::move(v));
    return vars_.back().code;
  }

  const model::Matrix& m_;
  model::InputTable table_;
  std::vector<model::Observable> obs_;
  std::vector<Var> vars_;
  std::ostringstream defs_;
  std::size_t cycles_ = 0;
};

}  // namespace

std::string vcd(const model::Matrix& m, const checker::ConcreteTrace& t, const VcdHeader& h) {
  Dump d(m);
  d.defs() << "$scope module " << word(m.name) << " $end\n";
  d.run(t);
  d.defs() << "$upscope $end\n";
  return d.text(h, std::to_string(t.inputs.size()) + " cycles");
}

std::string vcd_runs(const model::Matrix& m, const std::vector<VcdRun>& runs, const VcdHeader& h) {
  Dump d(m);
  d.defs() << "$scope module " << word(m.name) << " $end\n";
  std::string what = std::to_string(runs.size()) + (runs.size() == 1 ? " run" : " runs") + ", each from time 0:";
  for (const auto& r : runs) {
    d.defs() << "$scope module " << word(r.scope) << " $end\n";
    d.run(*r.trace);
    d.defs() << "$upscope $end\n";
    what += " " + word(r.scope) + " (" + std::to_string(r.trace->inputs.size()) + " cycles)";
  }
  d.defs() << "$upscope $end\n";
  return d.text(h, what);
}

}  // namespace cemv::reports
