// Validation of intersections and XooN voting (6.5.2).
#include "model/validate_checks.hpp"

#include <set>
#include <string>
#include <utility>

#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::model::validation {

namespace {

class IntersectionChecks : public Checks {
 public:
  using Checks::Checks;

  void run() {
    intersections();
    xoon();
  }

 private:
  // ---- intersections ---------------------------------------------------------

  void intersections() {
    std::set<std::pair<int, int>> seen;
    for (const auto& x : m_.intersections) {
      const Where w = at(x);
      const Cause* c = cause_by_id(x.cause);
      const Effect* e = effect_by_id(x.effect);
      if (!c || !e) {
        std::string missing = !c ? "cause " + std::to_string(x.cause) : "";
        if (!e) missing += (missing.empty() ? "" : " and ") + ("effect " + std::to_string(x.effect));
        add("E-INTERSECTION-DANGLING", w, missing + " does not exist");
      }
      if (!seen.insert({x.cause, x.effect}).second)
        add("E-INTERSECTION-REPEATED", w,
            "a second intersection (type " + std::string(to_string(x.type)) +
                ") for the same cause and effect");
      if (x.type == IntersectionType::X)
        add("E-INTERSECTION-X", w,
            "intersection type X is not yet specified: the matrix can be neither verified nor "
            "transferred until the type is chosen");
      if (x.type != IntersectionType::Note && c && e && (!processed(*c) || !processed(*e)))
        add("E-COMMENT-INTERSECTION", w,
            "type " + std::string(to_string(x.type)) + " links " +
                (!processed(*c) ? "a comment-only cause" : "a comment-only effect") +
                ": it is never processed (use '*' for a note)");
    }
  }

  // XooN majority assignment (6.5.2): X from the user, N the number of the
  // effect's intersections carrying X, one assignment per effect, one type.
  void xoon() {
    std::map<int, std::vector<const Intersection*>> by_effect;
    for (const auto& x : m_.intersections)
      if (x.xoon) by_effect[x.effect].push_back(&x);
    for (const auto& [effect_id, xs] : by_effect) {
      const Effect* e = effect_by_id(effect_id);
      Where w = e ? at(*e) : Where{2, effect_id, 0, "effect[" + std::to_string(effect_id) + "]"};
      int n = static_cast<int>(xs.size());
      std::set<int> xvals;
      std::set<IntersectionType> types;
      for (const auto* x : xs) {
        if (*x->xoon < kMinXooN || *x->xoon > kMaxXooN)
          add("E-XOON-RANGE", at(*x),
              "xoon " + std::to_string(*x->xoon) + " is outside " + std::to_string(kMinXooN) +
                  "-" + std::to_string(kMaxXooN));
        if (x->type == IntersectionType::Note)
          add("E-XOON-NOT-PROCESSED", at(*x),
              "xoon " + std::to_string(*x->xoon) +
                  " on a '*' (note only) intersection, which is never processed");
        xvals.insert(*x->xoon);
        types.insert(x->type);
      }
      if (xvals.size() > 1) {
        std::string list;
        for (int v : xvals) list += (list.empty() ? "" : ", ") + std::to_string(v);
        add("E-XOON-MIXED-X", w,
            "the intersections carry X = " + list +
                ": only one XooN assignment is allowed per effect");
      }
      if (types.size() > 1) {
        std::string list;
        for (auto t : types) list += (list.empty() ? "" : ", ") + std::string(to_string(t));
        add("E-XOON-MIXED-TYPE", w,
            "the XooN intersections have types " + list + ": they must all be of one type");
      }
      int x_max = *xvals.rbegin();
      if (x_max > n)
        add("E-XOON-COUNT", w,
            std::to_string(x_max) + "oo" + std::to_string(n) + ": X exceeds N = " +
                std::to_string(n) + " (the number of the effect's intersections with an xoon "
                                     "value), so the assignment can never trip");
    }
  }
};

}  // namespace

void check_intersections(const Matrix& m, std::vector<Finding>& out) { IntersectionChecks(m, out).run(); }

}  // namespace cemv::model::validation
