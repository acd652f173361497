// The program's state and one scan as a transition system.
#include "plc_encoder/encode.hpp"

#include <cctype>

#include "plc_encoder/symbolic.hpp"

namespace cemv::plc_encoder {

namespace {

std::string upper(std::string s) {
  for (auto& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

class Builder {
 public:
  Builder(z3::context& ctx, const plc::Program& program, std::uint32_t scan_ms, std::string prefix)
      : ctx_(ctx), scan_(ctx, program, scan_ms), prefix_(std::move(prefix)) {}

  ProgramSystem build(const plc::Pou& pou) {
    declare(pou, "", true);
    Scope top;
    top.pou = &pou;
    Env env = start_;
    scan_.exec(pou.body, top, env);
    for (auto& s : out_.states) s.next = env.at(state_keys_[&s - out_.states.data()]);
    for (const auto& v : pou.variables)
      if (v.type.kind == plc::VarType::Kind::Elementary &&
          (v.section == plc::Section::Output || v.section == plc::Section::InOut))
        out_.outputs.push_back({v.name, v.type.type, env.at(upper(v.name))});
    out_.real_literals.assign(scan_.real_literals().begin(), scan_.real_literals().end());
    return std::move(out_);
  }

 private:
  void state(const std::string& key, const z3::sort& sort, const z3::expr& init) {
    z3::expr var = ctx_.constant((prefix_ + key).c_str(), sort);
    out_.states.push_back({prefix_ + key, var, init, var});
    state_keys_.push_back(key);
    start_.insert_or_assign(key, var);
  }

  z3::expr initial(const plc::Variable& v) {
    return v.initial ? scan_.literal(*v.initial) : scan_.zero(v.type.type);
  }

  void declare(const plc::Pou& pou, const std::string& path, bool top) {
    for (const auto& v : pou.variables) {
      const std::string key = path + upper(v.name);
      switch (v.type.kind) {
        case plc::VarType::Kind::Elementary:
          if (v.section == plc::Section::Constant) {
            start_.insert_or_assign(key, initial(v));
          } else if (top && (v.section == plc::Section::Input || v.section == plc::Section::InOut)) {
            z3::expr in = ctx_.constant((prefix_ + "in." + v.name).c_str(), sort_of(ctx_, v.type.type));
            out_.inputs.push_back({v.name, v.type.type, in});
            start_.insert_or_assign(key, in);
          } else {
            state(key, sort_of(ctx_, v.type.type), initial(v));
          }
          break;
        case plc::VarType::Kind::Standard: standard(v.type.block, key); break;
        case plc::VarType::Kind::User: {
          const plc::Pou* inner = plc::find_pou(scan_.program(), v.type.user);
          if (!inner) throw Unsupported(v.position, "no FUNCTION_BLOCK " + v.type.user);
          if (++depth_ > 16) throw Unsupported(v.position, "block instances nested more than 16 deep");
          declare(*inner, key + ".", false);
          --depth_;
          break;
        }
      }
    }
  }

  void standard(plc::StandardBlock b, const std::string& key) {
    for (const auto& p : plc::block_pins(b))
      state(key + "." + std::string(plc::pin_name(p.pin)), sort_of(ctx_, p.type), scan_.zero(p.type));
    const z3::expr f = ctx_.bool_val(false);
    switch (b) {
      case plc::StandardBlock::RTrig:
      case plc::StandardBlock::FTrig: state(key + ".#M", ctx_.bool_sort(), f); break;
      case plc::StandardBlock::Ton:
      case plc::StandardBlock::Tof:
      case plc::StandardBlock::Tp:
        state(key + ".#PREV", ctx_.bool_sort(), f);
        state(key + ".#RUN", ctx_.bool_sort(), f);
        state(key + ".#DONE", ctx_.bool_sort(), f);
        state(key + ".#E", ctx_.int_sort(), ctx_.int_val(0));
        break;
      default: break;
    }
  }

  z3::context& ctx_;
  Scan scan_;
  std::string prefix_;
  ProgramSystem out_;
  std::vector<std::string> state_keys_;  // parallel to out_.states
  Env start_;
  int depth_ = 0;
};

}  // namespace

z3::sort sort_of(z3::context& ctx, plc::Type t) {
  switch (t) {
    case plc::Type::Bool: return ctx.bool_sort();
    case plc::Type::Int:
    case plc::Type::Dint:
    case plc::Type::Time: return ctx.int_sort();
    case plc::Type::Real: return ctx.fpa_sort<32>();
  }
  return ctx.bool_sort();
}

ProgramSystem encode(z3::context& ctx, const plc::Program& program, const plc::Pou& pou, std::uint32_t scan_ms,
                     const std::string& prefix) {
  Builder b(ctx, program, scan_ms, prefix);
  return b.build(pou);
}

}  // namespace cemv::plc_encoder
