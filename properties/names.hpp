// Name resolution of the property language against one matrix: causes and
// effects by id or name, their status fields under the names `cemv simulate`
// uses (model::cause_fields / effect_fields), input and output tags by name,
// and the element sets aggregates range over. Errors are plain messages; the
// parser adds the place.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// What a tag name stands for in an expression.
struct TagRef {
  std::string name;                        // as written in the matrix
  std::optional<std::size_t> input;        // InputTable index of an input tag
  std::optional<model::Observable> value;  // output tag or internal reference
};

// One element an aggregate variable is bound to.
struct Element {
  enum class Kind { Cause, Effect, Tag } kind = Kind::Cause;
  int id = 0;        // Cause / Effect
  TagRef tag;        // Tag
};

class MatrixNames {
 public:
  explicit MatrixNames(const model::Matrix& m);

  const model::Matrix& matrix() const { return m_; }
  const model::InputTable& inputs() const { return inputs_; }

  // A processed cause / effect by id ("12") or name (case-insensitive);
  // returns the id, or an error message with a did-you-mean hint.
  std::variant<int, std::string> cause(std::string_view id_or_name, bool is_number) const;
  std::variant<int, std::string> effect(std::string_view id_or_name, bool is_number) const;

  // `cause[id].field`, `effect[id].field`, `effect[id].tag[k]` as observables.
  std::variant<model::Observable, std::string> cause_field(int id, std::string_view field) const;
  std::variant<model::Observable, std::string> effect_field(int id, std::string_view field) const;
  std::variant<model::Observable, std::string> effect_tag(int id, long k) const;

  // A tag by name: an input tag, an output tag, or an internal reference
  // (Cause[x], Effect[x], Effect[x][y], 6.1.3).
  std::variant<TagRef, std::string> tag(std::string_view name) const;

  // The sets aggregates range over (docs/properties.md, "Aggregates").
  std::vector<Element> all_causes() const;
  std::vector<Element> all_effects() const;
  std::variant<std::vector<Element>, std::string> sif_causes(int group) const;
  std::variant<std::vector<Element>, std::string> sif_effects(int group) const;
  std::vector<Element> causes_of_effect(int effect) const;   // processed intersections
  std::vector<Element> effects_of_cause(int cause) const;
  std::vector<Element> tags_of_cause(int cause) const;       // its input tags
  std::vector<Element> tags_of_effect(int effect) const;     // its output tags

 private:
  std::optional<model::Observable> observable(const std::string& key) const;
  std::variant<std::vector<Element>, std::string> sif_members(int group, bool causes) const;

  const model::Matrix& m_;
  model::InputTable inputs_;
  std::vector<model::Observable> observables_;  // sorted by key
};

// The project's hint and quoting (model/text.hpp), for candidates held as strings.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);
std::string in_quotes(std::string_view text);

}  // namespace cemv::properties
