#include "reports/timing_table.hpp"

#include <algorithm>

#include "model/text.hpp"

namespace cemv::reports {

namespace {

// Boolean tags as 0/1, analog ones in their shortest float text; "(bad)"
// marks bad quality.
std::string input_text(const model::InputTag& t, const model::TagValue& v) {
  std::string s = t.kind == model::TagKind::Bool ? (v.value != 0.0f ? "1" : "0") : model::float_text(v.value);
  if (v.bad_quality) s += "(bad)";
  return s;
}

std::string observable_text(const model::Observable& o, int v) {
  if (o.type == model::FieldType::Voting) return model::to_string(static_cast<model::Voting>(v));
  return std::to_string(v);
}

}  // namespace

void TimingTable::Timeline::record(std::uint64_t cycle, std::string v) {
  if (points.empty() || points.back().second != v) points.emplace_back(cycle, std::move(v));
}

TimingTable::TimingTable(const model::InputTable& inputs, const std::vector<model::Observable>& observables)
    : inputs_(inputs), observables_(observables) {
  for (const auto& t : inputs.tags()) lines_.push_back({t.name, {}});
  for (const auto& o : observables) lines_.push_back({o.key, {}});
}

void TimingTable::record(std::uint64_t cycle_no, const model::CycleInput& in, const std::vector<int>& snapshot) {
  for (std::size_t i = 0; i < inputs_.size(); ++i)
    lines_[i].record(cycle_no, input_text(inputs_.tags()[i], in.tags[i]));
  for (std::size_t i = 0; i < observables_.size(); ++i)
    lines_[inputs_.size() + i].record(cycle_no, observable_text(observables_[i], snapshot[i]));
}

void TimingTable::print(std::ostream& out, std::uint32_t cycle_ms) const {
  std::size_t width = 0;
  for (const auto& l : lines_)
    if (l.points.size() > 1) width = std::max(width, l.name.size());
  out << "timing (cycle:value at the first cycle and at each change; cycle n is t = (n-1)*"
      << cycle_ms << " ms):\n";
  bool any = false;
  for (const auto& l : lines_) {
    if (l.points.size() <= 1) continue;
    any = true;
    out << "  " << l.name << std::string(width - l.name.size(), ' ');
    for (const auto& [c, v] : l.points) out << "  " << c << ":" << v;
    out << "\n";
  }
  if (!any) out << "  (no signal changes)\n";
}

}  // namespace cemv::reports
