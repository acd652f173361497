// A candidate evaluated on sampled states (sample_test.hpp).
#include "plc_check/sample_test.hpp"

namespace cemv::plc_check {

namespace {

// A variable's node kind: a column of the state, not a Z3 operator.
constexpr Z3_decl_kind kColumn = Z3_OP_UNINTERPRETED;

bool evaluated(Z3_decl_kind k) {
  switch (k) {
    case Z3_OP_TRUE: case Z3_OP_FALSE: case Z3_OP_NOT: case Z3_OP_AND: case Z3_OP_OR:
    case Z3_OP_IMPLIES: case Z3_OP_XOR: case Z3_OP_ITE:
    case Z3_OP_EQ: case Z3_OP_DISTINCT: case Z3_OP_IFF: case Z3_OP_LE: case Z3_OP_GE: case Z3_OP_LT: case Z3_OP_GT:
    case Z3_OP_ADD: case Z3_OP_SUB: case Z3_OP_UMINUS: case Z3_OP_MUL:
      return true;
    default:
      return false;
  }
}

}  // namespace

std::optional<SampleTest> SampleTest::compile(const z3::expr& c,
                                              const std::unordered_map<unsigned, std::size_t>& column) {
  SampleTest t;
  if (!t.add(c, column)) return std::nullopt;
  return t;
}

std::optional<std::size_t> SampleTest::add(const z3::expr& e, const std::unordered_map<unsigned, std::size_t>& column) {
  Node n{};
  std::int64_t k = 0;
  if (e.is_numeral()) {
    if (!e.is_int() || !e.is_numeral_i64(k)) return std::nullopt;
    n.kind = Z3_OP_ANUM;
    n.value = k;
  } else if (!e.is_app()) {
    return std::nullopt;
  } else if (e.is_const() && e.decl().decl_kind() == Z3_OP_UNINTERPRETED) {
    const auto it = column.find(e.id());
    if (it == column.end() || !(e.is_bool() || e.is_int())) return std::nullopt;
    n.kind = kColumn;
    n.value = static_cast<std::int64_t>(it->second);
  } else {
    n.kind = e.decl().decl_kind();
    if (!evaluated(n.kind)) return std::nullopt;
    // A product is evaluated only by a numeral: the candidates' coefficients.
    if (n.kind == Z3_OP_MUL && (e.num_args() != 2 || !(e.arg(0).is_numeral() || e.arg(1).is_numeral())))
      return std::nullopt;
    for (unsigned i = 0; i < e.num_args(); ++i) {
      const auto a = add(e.arg(i), column);
      if (!a) return std::nullopt;
      n.args.push_back(*a);
    }
  }
  nodes_.push_back(std::move(n));
  return nodes_.size() - 1;
}

bool SampleTest::holds(const std::vector<encoder::Evaluator::Value>& state) const {
  return eval(nodes_.size() - 1, state) != 0;
}

std::int64_t SampleTest::eval(std::size_t node, const std::vector<encoder::Evaluator::Value>& state) const {
  const Node& n = nodes_[node];
  auto arg = [&](std::size_t i) { return eval(n.args[i], state); };
  switch (n.kind) {
    case Z3_OP_ANUM: return n.value;
    case kColumn: return state[static_cast<std::size_t>(n.value)].i;
    case Z3_OP_TRUE: return 1;
    case Z3_OP_FALSE: return 0;
    case Z3_OP_NOT: return arg(0) == 0;
    case Z3_OP_AND:
      for (std::size_t i = 0; i < n.args.size(); ++i)
        if (arg(i) == 0) return 0;
      return 1;
    case Z3_OP_OR:
      for (std::size_t i = 0; i < n.args.size(); ++i)
        if (arg(i) != 0) return 1;
      return 0;
    case Z3_OP_IMPLIES: return arg(0) == 0 || arg(1) != 0;
    case Z3_OP_XOR: return (arg(0) != 0) != (arg(1) != 0);
    case Z3_OP_ITE: return arg(0) != 0 ? arg(1) : arg(2);
    case Z3_OP_EQ: case Z3_OP_IFF: return arg(0) == arg(1);
    case Z3_OP_DISTINCT:
      for (std::size_t i = 0; i < n.args.size(); ++i)
        for (std::size_t j = i + 1; j < n.args.size(); ++j)
          if (arg(i) == arg(j)) return 0;
      return 1;
    case Z3_OP_LE: return arg(0) <= arg(1);
    case Z3_OP_GE: return arg(0) >= arg(1);
    case Z3_OP_LT: return arg(0) < arg(1);
    case Z3_OP_GT: return arg(0) > arg(1);
    case Z3_OP_UMINUS: return -arg(0);
    case Z3_OP_ADD: {
      std::int64_t s = 0;
      for (std::size_t i = 0; i < n.args.size(); ++i) s += arg(i);
      return s;
    }
    case Z3_OP_SUB: {
      std::int64_t s = arg(0);
      for (std::size_t i = 1; i < n.args.size(); ++i) s -= arg(i);
      return s;
    }
    case Z3_OP_MUL: return arg(0) * arg(1);
    default: return 1;  // not compiled
  }
}

}  // namespace cemv::plc_check
