// What each header row (label column) of a C&E grid holds, read from its
// values (docs/csv.md "Stacked effect header"): output tags (`XV-301`), SIL
// levels (`SIL 2`), action verbs (`CLOSE`), numbers or ids (`1`, `TMA-A-1`),
// or free text (descriptions). A contractor stacks these rows in any order,
// with or without labels: no row is the id for being nearest the grid. A label
// that agrees is evidence, one that contradicts the values is refused, and two
// rows that could each be the tag (SIL, id) row are refused, never one picked.
#include <algorithm>
#include <map>
#include <regex>
#include <set>

#include "sheets/csv_grid.hpp"
#include "sheets/csv_grid_values.hpp"
#include "formats/csv_text.hpp"
#include "model/text.hpp"

namespace cemv::formats::grid {

using namespace csv_text;
using model::in_quotes;

namespace {

enum class CellKind { Nil, Tag, Sil, Action, SmallNumber, Number, Id, Text };

std::string letters_upper(std::string_view text) {
  std::string out;
  for (char c : text)
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) out += static_cast<char>(c & ~0x20);
  return out;
}

bool all_digits(std::string_view t) {
  return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
}

CellKind cell_kind(const std::string& text) {
  const std::string t(trim(text));
  if (t.empty() || nil_value(t)) return CellKind::Nil;
  static const std::regex sil(R"(^sil\s*[-:]?\s*[0-4]$)", std::regex::icase);
  if (std::regex_match(t, sil)) return CellKind::Sil;
  if (action_word(t)) return CellKind::Action;
  if (all_digits(t)) return t.size() == 1 && t[0] <= '4' ? CellKind::SmallNumber : CellKind::Number;
  const auto tags = split_tags(t);
  if (!tags.empty() && std::all_of(tags.begin(), tags.end(), [](const std::string& s) { return tag_shaped(s); }))
    return CellKind::Tag;
  const bool blank = t.find_first_of(" \t") != std::string::npos;
  const bool letter = std::any_of(t.begin(), t.end(), [](char c) { return (c | 0x20) >= 'a' && (c | 0x20) <= 'z'; });
  const bool digit = std::any_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
  return !blank && letter && digit ? CellKind::Id : CellKind::Text;
}

// What a row's (column's) values hold, with up to three of them as examples.
struct Content {
  HeaderContent kind = HeaderContent::Text;
  std::vector<std::string> examples;
  bool repeats = false;  // a value written twice (ids do not repeat)
};

// What the values are: SIL levels and action verbs all of them; tags, or
// numbers, ids and tags together (ids), more than half of them (a row of ids
// with a note right of the grid is still the id row); else free text.
Content content_of(const std::vector<std::string>& values) {
  Content c;
  std::map<CellKind, int> count;
  std::set<std::string> seen;
  int n = 0;
  for (const auto& v : values) {
    const CellKind k = cell_kind(v);
    if (k == CellKind::Nil) continue;
    ++n;
    ++count[k];
    if (!seen.insert(v).second) c.repeats = true;
    if (c.examples.size() < 3) c.examples.push_back(v);
  }
  auto most = [&](int k) { return n > 0 && 2 * k > n; };
  const int small = count[CellKind::SmallNumber];
  if (most(count[CellKind::Tag])) c.kind = HeaderContent::Tags;
  else if (count[CellKind::Sil] > 0 && count[CellKind::Sil] + small == n) c.kind = HeaderContent::Sil;
  else if (n > 0 && count[CellKind::Action] == n) c.kind = HeaderContent::Actions;  // `Open, Close, Vent`: text
  else if (most(small) && small + count[CellKind::Text] == n) c.kind = HeaderContent::SmallNumbers;
  else if (most(small + count[CellKind::Number] + count[CellKind::Id] + count[CellKind::Tag])) c.kind = HeaderContent::Ids;
  else c.kind = HeaderContent::Text;
  return c;
}

std::string examples_of(const Content& c) {
  std::string list;
  for (const auto& e : c.examples) join_to(list, ", ", in_quotes(truncate_utf8(e, 30)));
  return list;
}

std::string content_words(const Content& c) {
  switch (c.kind) {
    case HeaderContent::Tags: return "tag-shaped values " + examples_of(c);
    case HeaderContent::Sil: return "SIL levels " + examples_of(c);
    case HeaderContent::Actions: return "action verbs " + examples_of(c);
    case HeaderContent::SmallNumbers: return std::string(c.repeats ? "repeated " : "") + "numbers 0-4 " + examples_of(c);
    case HeaderContent::Ids: return "ids " + examples_of(c);
    case HeaderContent::Text: return "free text " + examples_of(c);
  }
  return "";
}

// The attribute the values say, when they say one by themselves.
std::optional<SheetAttribute> attribute_of_content(HeaderContent k) {
  switch (k) {
    case HeaderContent::Tags: return SheetAttribute::Tag;
    case HeaderContent::Sil: return SheetAttribute::Sil;
    case HeaderContent::Actions: return SheetAttribute::Action;
    default: return std::nullopt;
  }
}

// A label against what its values are: SIL over tags, Tag over verbs, ...
bool contradicts(SheetAttribute label, const Content& c) {
  using A = SheetAttribute;
  const bool named = label == A::Tag || label == A::Sil || label == A::Action || label == A::Description;
  switch (c.kind) {
    case HeaderContent::Tags: return named && label != A::Tag;
    case HeaderContent::Sil: return (named || label == A::Id) && label != A::Sil;
    case HeaderContent::Actions: return (named || label == A::Id) && label != A::Action;
    case HeaderContent::SmallNumbers: return label == A::Tag || label == A::Action || label == A::Description;
    case HeaderContent::Ids:
      // A SIL label over numbers beyond 0-4, or over ids, is no SIL row.
      return label == A::Sil || label == A::Action;
    case HeaderContent::Text: return false;
  }
  return false;
}

std::string names_of(const std::vector<const HeaderCandidate*>& cs) {
  std::string list;
  for (const auto* c : cs)
    join_to(list, "; ", c->name + (c->label.empty() ? "" : " " + in_quotes(c->label)) + " (" +
                            content_words(content_of(c->values)) + ")");
  return list;
}

}  // namespace

bool tag_shaped(std::string_view text) {
  // Letters, a separator, digits (ISA 5.1 instrument and equipment tags), an
  // optional area number before and suffix letters after.
  static const std::regex tag(R"(^([0-9]{1,4}[-_.])?[A-Za-z]{1,6}[-_.][0-9]{2,6}[A-Za-z]{0,2}$)");
  return std::regex_match(std::string(trim(text)), tag);
}

bool action_word(std::string_view text) {
  static const std::set<std::string> verbs{
      "CLOSE",      "CLOSED",      "CLOSES",      "SHUT",       "OPEN",       "OPENS",      "OPENED",
      "STOP",       "STOPS",       "STOPPED",     "TRIP",       "TRIPS",      "TRIPPED",    "START",
      "STARTS",     "STARTED",     "DEENERGISE",  "DEENERGIZE", "DEENERGISED", "DEENERGIZED", "ENERGISE",
      "ENERGIZE",   "ENERGISED",   "ENERGIZED"};
  const std::string_view t = trim(text);
  // Letters, blanks and hyphens only: `DE-ENERGISE`, `De energise`.
  if (t.empty() || !std::all_of(t.begin(), t.end(), [](char c) {
        return c == '-' || c == ' ' || ((c | 0x20) >= 'a' && (c | 0x20) <= 'z');
      }))
    return false;
  return verbs.count(letters_upper(t)) > 0;
}

namespace {

// Reads what each header row (or label column) holds: by its label where it
// has one, else by its values; then places the tag, the id, the description
// and the notes, and refuses wherever two places fit (docs/csv.md, "Stacked
// effect header").
class HeaderClassifier {
 public:
  HeaderClassifier(const std::vector<HeaderCandidate>& candidates, bool header_rows)
      : candidates_(candidates),
        line_(header_rows ? "row" : "column"),
        lines_(header_rows ? "header rows" : "label columns"),
        elements_(header_rows ? "elements on the columns" : "elements on the rows") {}

  std::vector<Slot> classify() {
    for (const HeaderCandidate& c : candidates_) sort_candidate(c);
    refuse_ambiguous();
    place_unlabelled_tags();
    place_ids();
    name_elements();
    place_texts();
    if (problems_.empty()) let_description_name_elements();
    if (!problems_.empty()) throw LoadError(problems_);
    std::stable_sort(read_.begin(), read_.end(), [](const Slot& a, const Slot& b) { return a.index < b.index; });
    return read_;
  }

 private:
  using Candidates = std::vector<const HeaderCandidate*>;
  static constexpr const char* kLayoutHint =
      "give their places in the layout (\"effects\" or \"causes\", with the "
      "orientation; docs/csv.md \"Stacked effect header\")";

  bool has(SheetAttribute a) const {
    return std::any_of(read_.begin(), read_.end(), [a](const Slot& s) { return s.attribute == a; });
  }
  void push(const HeaderCandidate* c, SheetAttribute a) {
    read_.push_back(Slot{a, c->index, c->label, false, content_words(content_of(c->values))});
  }
  void refuse(const Candidates& cs, const std::string& what) {
    problems_.push_back({cs.front()->place, what + ": " + names_of(cs) + "; label the " + lines_ +
                                                " (Tag, SIL, Action, Item, Description) or " + kLayoutHint});
  }

  void sort_candidate(const HeaderCandidate& c) {
    const Content content = content_of(c.values);
    if (attribute_of_header(c.label)) {
      read_label(c, content);
      return;
    }
    Slot s;
    s.index = c.index;
    s.label = c.label;
    s.evidence = content_words(content);
    switch (content.kind) {
      case HeaderContent::Tags: tags_by_content_.push_back(&c); break;
      case HeaderContent::Sil:
        sils_.push_back(&c);
        s.attribute = SheetAttribute::Sil;
        stacked_ = true;
        read_.push_back(s);
        break;
      case HeaderContent::Actions:
        s.attribute = SheetAttribute::Action;
        stacked_ = true;
        read_.push_back(s);
        break;
      case HeaderContent::SmallNumbers:
        // `2, 2, 1`: SIL levels without their label, or ids? Ids do not repeat.
        if (content.repeats) ambiguous_.push_back(&c);
        else ids_.push_back(&c);
        break;
      case HeaderContent::Ids: ids_.push_back(&c); break;
      case HeaderContent::Text: texts_.push_back(&c); break;
    }
  }

  // A labelled row or column: its label says what it is, unless its values
  // contradict it; an attribute given twice is a note the second time.
  void read_label(const HeaderCandidate& c, const Content& content) {
    Slot s;
    s.index = c.index;
    s.label = c.label;
    s.attribute = attribute_of_header(c.label)->attribute;
    s.by_header = true;
    if (contradicts(s.attribute, content)) {
      problems_.push_back({c.place, c.name + " is labelled " + in_quotes(c.label) + " (" + to_string(s.attribute) +
                                        ") but holds " + content_words(content) + ": correct the label, or " +
                                        kLayoutHint});
      return;
    }
    const auto said = attribute_of_content(content.kind);
    s.evidence = said == s.attribute || (s.attribute == SheetAttribute::Sil && content.kind == HeaderContent::SmallNumbers)
                     ? "its label and " + content_words(content)
                     : "its label";
    const bool once = s.attribute != SheetAttribute::Note && s.attribute != SheetAttribute::Tag &&
                      s.attribute != SheetAttribute::Action;
    if (once && has(s.attribute)) s.attribute = SheetAttribute::Note;
    if (s.attribute == SheetAttribute::Tag) tags_by_label_.push_back(&c);
    if (s.attribute == SheetAttribute::Sil) sils_.push_back(&c);
    stacked_ = stacked_ || s.attribute == SheetAttribute::Sil || s.attribute == SheetAttribute::Action;
    read_.push_back(s);
  }

  void refuse_ambiguous() {
    for (const auto* c : ambiguous_) refuse({c}, "cannot tell whether " + c->name + " holds SIL levels or ids");
    if (sils_.size() > 1) refuse(sils_, "two or more " + lines_ + " could each be the SIL " + line_);
    labelled_id_ = has(SheetAttribute::Id);
  }

  // Tag-shaped values under no label: the tag row, unless a labelled tag row
  // leaves it to be the id.
  void place_unlabelled_tags() {
    if (tags_by_content_.empty()) return;
    if (tags_by_label_.empty() && tags_by_content_.size() == 1) {
      read_.push_back(Slot{SheetAttribute::Tag, tags_by_content_[0]->index, "", false,
                           content_words(content_of(tags_by_content_[0]->values))});
    } else if (!tags_by_label_.empty() && tags_by_content_.size() == 1 && !labelled_id_ && ids_.empty()) {
      ids_.push_back(tags_by_content_[0]);
    } else {
      Candidates all = tags_by_label_;
      all.insert(all.end(), tags_by_content_.begin(), tags_by_content_.end());
      refuse(all, "two or more " + lines_ + " could each be the tag " + line_);
    }
  }

  // One unlabelled row of ids is the id row; several are refused in a stacked
  // header and read by position in a plain grid (`d1`, `d2` over `E1`, `E2`).
  void place_ids() {
    if (!labelled_id_) {
      if (ids_.size() == 1) {
        push(ids_[0], SheetAttribute::Id);
        ids_.clear();
      } else if (ids_.size() > 1) {
        if (stacked_ || has(SheetAttribute::Tag)) {
          refuse(ids_, "two or more " + lines_ + " could each be the id " + line_);
        } else {
          texts_.insert(texts_.end(), ids_.begin(), ids_.end());
          std::sort(texts_.begin(), texts_.end(), [](const auto* a, const auto* b) { return a->index < b->index; });
        }
        ids_.clear();
      }
    }
    for (const auto* c : ids_) push(c, SheetAttribute::Note);
  }

  // Without an id row the tags name the elements; a stacked header without
  // either is refused (free text is a description, never an id); a plain
  // grid's last unlabelled row is the id, by position.
  void name_elements() {
    if (has(SheetAttribute::Id)) return;
    const Slot* tag = nullptr;
    for (const Slot& s : read_)
      if (s.attribute == SheetAttribute::Tag && !tag) tag = &s;
    if (tag) {
      Slot id = *tag;
      id.attribute = SheetAttribute::Id;
      id.evidence = "no id " + line_ + ": the tags name the " + elements_;
      read_.push_back(id);
    } else if (stacked_ && problems_.empty()) {
      Candidates all;
      for (const HeaderCandidate& c : candidates_) all.push_back(&c);
      refuse(all, "no " + line_ + " holds the tags or ids of the " + elements_ + " (values such as 'XV-301' or '1')");
    } else if (!texts_.empty()) {
      push(texts_.back(), SheetAttribute::Id);
      read_.back().evidence = "the last unlabelled " + line_ + ", by position";
      texts_.pop_back();
    }
  }

  // The first free text is the description unless one is labelled; the rest are notes.
  void place_texts() {
    const bool has_description = has(SheetAttribute::Description);
    for (std::size_t k = 0; k < texts_.size(); ++k)
      push(texts_[k], k == 0 && !has_description ? SheetAttribute::Description : SheetAttribute::Note);
  }

  // Nothing else left (a lone labelled description): the description is the id.
  void let_description_name_elements() {
    if (has(SheetAttribute::Id)) return;
    for (std::size_t k = 0; k < read_.size(); ++k)
      if (read_[k].attribute == SheetAttribute::Description) {
        Slot id = read_[k];
        id.attribute = SheetAttribute::Id;
        id.evidence = "no id " + line_ + ": the descriptions name the " + elements_;
        read_.push_back(id);
        return;
      }
  }

  const std::vector<HeaderCandidate>& candidates_;
  const std::string line_, lines_, elements_;
  std::vector<Slot> read_;
  std::vector<LoadIssue> problems_;
  Candidates ids_, texts_, tags_by_content_, tags_by_label_, sils_, ambiguous_;
  bool stacked_ = false;      // a row read as SIL or action: a contractor's stacked header
  bool labelled_id_ = false;  // an id row by its label
};

}  // namespace

std::vector<Slot> classify_headers(const std::vector<HeaderCandidate>& candidates, bool header_rows) {
  return HeaderClassifier(candidates, header_rows).classify();
}

}  // namespace cemv::formats::grid
