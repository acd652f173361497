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

std::vector<Slot> classify_headers(const std::vector<HeaderCandidate>& candidates, bool header_rows) {
  const std::string line = header_rows ? "row" : "column";
  const std::string lines = header_rows ? "header rows" : "label columns";
  const std::string elements = header_rows ? "elements on the columns" : "elements on the rows";
  const std::string layout_hint = "give their places in the layout (\"effects\" or \"causes\", with the "
                                  "orientation; docs/csv.md \"Stacked effect header\")";
  std::vector<Slot> read;
  std::vector<LoadIssue> problems;
  std::vector<const HeaderCandidate*> ids, texts, tags_by_content, tags_by_label, sils, ambiguous;
  bool stacked = false;  // a row read as SIL or action by its values: a contractor's stacked header
  for (const HeaderCandidate& c : candidates) {
    const Content content = content_of(c.values);
    Slot s;
    s.index = c.index;
    s.label = c.label;
    if (const auto meaning = attribute_of_header(c.label)) {
      s.attribute = meaning->attribute;
      s.by_header = true;
      if (contradicts(s.attribute, content)) {
        problems.push_back({c.place, c.name + " is labelled " + in_quotes(c.label) + " (" + to_string(s.attribute) +
                                         ") but holds " + content_words(content) +
                                         ": correct the label, or " + layout_hint});
        continue;
      }
      const auto said = attribute_of_content(content.kind);
      s.evidence = said == s.attribute || (s.attribute == SheetAttribute::Sil && content.kind == HeaderContent::SmallNumbers)
                       ? "its label and " + content_words(content)
                       : "its label";
      const bool once = s.attribute != SheetAttribute::Note && s.attribute != SheetAttribute::Tag &&
                        s.attribute != SheetAttribute::Action;
      if (once && std::any_of(read.begin(), read.end(), [&](const Slot& o) { return o.attribute == s.attribute; }))
        s.attribute = SheetAttribute::Note;
      if (s.attribute == SheetAttribute::Tag) tags_by_label.push_back(&c);
      if (s.attribute == SheetAttribute::Sil) sils.push_back(&c);
      stacked = stacked || s.attribute == SheetAttribute::Sil || s.attribute == SheetAttribute::Action;
      read.push_back(s);
      continue;
    }
    s.evidence = content_words(content);
    switch (content.kind) {
      case HeaderContent::Tags: tags_by_content.push_back(&c); break;
      case HeaderContent::Sil:
        sils.push_back(&c);
        s.attribute = SheetAttribute::Sil;
        stacked = true;
        read.push_back(s);
        break;
      case HeaderContent::Actions:
        s.attribute = SheetAttribute::Action;
        stacked = true;
        read.push_back(s);
        break;
      case HeaderContent::SmallNumbers:
        // `2, 2, 1`: SIL levels without their label, or ids? Ids do not repeat.
        if (content.repeats) ambiguous.push_back(&c);
        else ids.push_back(&c);
        break;
      case HeaderContent::Ids: ids.push_back(&c); break;
      case HeaderContent::Text: texts.push_back(&c); break;
    }
  }
  auto refuse = [&](const std::vector<const HeaderCandidate*>& cs, const std::string& what) {
    problems.push_back({cs.front()->place, what + ": " + names_of(cs) + "; label the " + lines +
                                               " (Tag, SIL, Action, Item, Description) or " + layout_hint});
  };
  for (const auto* c : ambiguous)
    refuse({c}, "cannot tell whether " + c->name + " holds SIL levels or ids");
  if (sils.size() > 1) refuse(sils, "two or more " + lines + " could each be the SIL " + line);
  const bool labelled_id = std::any_of(read.begin(), read.end(), [](const Slot& s) { return s.attribute == SheetAttribute::Id; });
  // Tag-shaped values under no label: the tag row, unless a labelled tag row
  // leaves it to be the id.
  if (!tags_by_content.empty()) {
    if (tags_by_label.empty() && tags_by_content.size() == 1) {
      Slot s{SheetAttribute::Tag, tags_by_content[0]->index, "", false,
             content_words(content_of(tags_by_content[0]->values))};
      read.push_back(s);
    } else if (!tags_by_label.empty() && tags_by_content.size() == 1 && !labelled_id && ids.empty()) {
      ids.push_back(tags_by_content[0]);
    } else {
      std::vector<const HeaderCandidate*> all = tags_by_label;
      all.insert(all.end(), tags_by_content.begin(), tags_by_content.end());
      refuse(all, "two or more " + lines + " could each be the tag " + line);
    }
  }
  auto push = [&](const HeaderCandidate* c, SheetAttribute a) {
    read.push_back(Slot{a, c->index, c->label, false, content_words(content_of(c->values))});
  };
  if (!labelled_id) {
    if (ids.size() == 1) {
      push(ids[0], SheetAttribute::Id);
      ids.clear();
    } else if (ids.size() > 1) {
      const bool has_tag = std::any_of(read.begin(), read.end(), [](const Slot& s) { return s.attribute == SheetAttribute::Tag; });
      if (stacked || has_tag) {
        refuse(ids, "two or more " + lines + " could each be the id " + line);
      } else {
        // A plain grid (`d1`, `d2` over `E1`, `E2`): by position, below.
        texts.insert(texts.end(), ids.begin(), ids.end());
        std::sort(texts.begin(), texts.end(), [](const auto* a, const auto* b) { return a->index < b->index; });
      }
      ids.clear();
    }
  }
  for (const auto* c : ids) push(c, SheetAttribute::Note);
  const bool has_id = std::any_of(read.begin(), read.end(), [](const Slot& s) { return s.attribute == SheetAttribute::Id; });
  const Slot* tag = nullptr;
  for (const Slot& s : read)
    if (s.attribute == SheetAttribute::Tag && !tag) tag = &s;
  if (!has_id && tag) {
    // No id row: the tags name the elements.
    Slot id = *tag;
    id.attribute = SheetAttribute::Id;
    id.evidence = "no id " + line + ": the tags name the " + elements;
    read.push_back(id);
  } else if (!has_id && stacked && problems.empty()) {
    // A stacked header names its elements by an id or a tag row; free text is
    // a description, never an id.
    std::vector<const HeaderCandidate*> all;
    for (const HeaderCandidate& c : candidates) all.push_back(&c);
    refuse(all, "no " + line + " holds the tags or ids of the " + elements + " (values such as 'XV-301' or '1')");
  } else if (!has_id && !texts.empty()) {
    // A plain grid: the last unlabelled one is the id (docs/csv.md "Header rows and label columns").
    push(texts.back(), SheetAttribute::Id);
    read.back().evidence = "the last unlabelled " + line + ", by position";
    texts.pop_back();
  }
  const bool has_description = std::any_of(read.begin(), read.end(), [](const Slot& s) {
    return s.attribute == SheetAttribute::Description;
  });
  for (std::size_t k = 0; k < texts.size(); ++k)
    push(texts[k], k == 0 && !has_description ? SheetAttribute::Description : SheetAttribute::Note);
  // Nothing else left (a lone labelled description): the description is the id.
  const bool id_now = std::any_of(read.begin(), read.end(), [](const Slot& s) { return s.attribute == SheetAttribute::Id; });
  for (std::size_t k = 0; k < read.size() && !id_now && problems.empty(); ++k)
    if (read[k].attribute == SheetAttribute::Description) {
      Slot id = read[k];
      id.attribute = SheetAttribute::Id;
      id.evidence = "no id " + line + ": the descriptions name the " + elements;
      read.push_back(id);
      break;
    }
  if (!problems.empty()) throw LoadError(problems);
  std::stable_sort(read.begin(), read.end(), [](const Slot& a, const Slot& b) { return a.index < b.index; });
  return read;
}

}  // namespace cemv::formats::grid
