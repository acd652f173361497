// The families of validation checks (validate.cpp runs them): each derives from
// Checks, which holds the matrix, its elements by id and the findings. Internal
// to model/.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "model/graph.hpp"
#include "model/matrix.hpp"
#include "model/validate.hpp"

namespace cemv::model::validation {


// Where a finding is, and how it sorts: matrix, then causes, effects and
// intersections by id.
struct Where {
  int rank = 0;
  int a = 0;
  int b = 0;
  std::string text;
};

Where at_matrix();
std::string cause_label(const Cause& c);
std::string effect_label(const Effect& e);
Where at(const Cause& c);
Where at(const Effect& e);
Where at(const Intersection& x);
Where at(const Node& n);

struct Finding {
  Where where;
  Diagnostic d;
};

// A finding of `rule` (one of validation_rules()) at `where`.
void record(std::vector<Finding>& out, std::string_view rule, const Where& where, std::string message);

// What every family of checks reads and where it records: nothing here assumes
// the loader ran (ids may repeat, intersections may dangle).
class Checks {
 public:
  Checks(const Matrix& m, std::vector<Finding>& out);

 protected:
  const Matrix& m_;

  void add(std::string_view rule, const Where& where, std::string message);
  const Cause* cause_by_id(int id) const;
  const Effect* effect_by_id(int id) const;
  static bool processed(const Cause& c) { return c.function != CauseFunction::Comment; }
  static bool processed(const Effect& e) { return e.function != EffectFunction::Comment; }
  // Intersections of an effect that exist and are valid links (both ends exist).
  std::vector<const Intersection*> links_of_effect(int effect) const;

 private:
  std::multimap<int, const Cause*> causes_by_id_;
  std::multimap<int, const Effect*> effects_by_id_;
  std::vector<Finding>& out_;
};

// The matrix's own fields, ids and names, each cause and effect (validate_elements.cpp).
void check_elements(const Matrix& m, std::vector<Finding>& out);
// Intersections and XooN voting (validate_intersections.cpp).
void check_intersections(const Matrix& m, std::vector<Finding>& out);
// External tags and internal references (validate_tags.cpp).
void check_tags(const Matrix& m, std::vector<Finding>& out);
// Missing intersection configurations and simulation permissions (validate_graph.cpp).
void check_graph(const Matrix& m, std::vector<Finding>& out);

}  // namespace cemv::model::validation
