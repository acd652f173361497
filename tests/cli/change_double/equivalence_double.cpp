// TEST DOUBLE of checker::decide_equivalence (see README.md): defined here so
// that the linker never takes the real equivalence.o from cemv_checker; the
// observable groups and the verdict's text are the real ones
// (checker/observable_groups.cpp). The verdict is chosen by a word in a name.
#include <algorithm>
#include <cctype>
#include <string>

#include "checker/equivalence.hpp"
#include "checker/prover.hpp"
#include "cli/commands.hpp"

namespace cemv::checker {

namespace {

bool has(std::string s, const char* word) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.find(word) != std::string::npos;
}

}  // namespace

GroupEquivalence decide_equivalence(const model::Matrix& a, const model::Matrix& b, const ObservableGroup& group,
                                    const EquivalenceOptions&) {
  std::string name = a.name;
  if (!group.roots.empty()) {
    const int id = group.roots.front().id;
    const model::Effect* e = b.find_effect(id) ? b.find_effect(id) : a.find_effect(id);
    name = e ? e->name : "";
  }
  if (has(name, "internal"))
    throw InternalError("equivalence of " + group.name + ": the runtimes do not reproduce the distinguishing run "
                        "(test double)");
  GroupEquivalence r;
  r.group = group.name;
  if (has(name, "undecided")) {
    r.verdict = EquivalenceVerdict::Unknown;
    r.method = "test double";
    r.reason = "time limit";
    return r;
  }
  r.verdict = EquivalenceVerdict::Equivalent;
  r.method = "test double";
  return r;
}

}  // namespace cemv::checker

// The commands main.cpp registers beside diff and mutate under
// CEMV_WITH_VERIFICATION, absent from this double.
namespace cemv::cli {
void add_response_commands(CLI::App&, Context&) {}
void add_evidence_commands(CLI::App&, Context&) {}
}  // namespace cemv::cli
