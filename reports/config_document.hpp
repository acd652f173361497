// The configuration report's document (docs/reports.md, manual section 11.4):
// built once from the matrix as headings, paragraphs and tables, then rendered
// to Markdown or HTML, so both forms always say the same thing; the JSON form
// carries the same sections as data. Internal to reports/.
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/validate.hpp"

namespace cemv::reports::config {

struct Text {
  std::string text;
  bool code = false;       // an identifier (name, tag): monospace, never reflowed
  std::string css;         // HTML class of a grid cell
};

inline Text code(std::string s) { return Text{std::move(s), true, {}}; }
inline Text plain(std::string s) { return Text{std::move(s), false, {}}; }

struct Heading {
  int level;
  std::string text;
  std::string anchor;
};
struct Paragraph {
  std::vector<Text> parts;  // concatenated
};
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<Text>> rows;
  bool grid = false;        // the C&E grid: compact cells
};
// One block of the document (not std::variant: GCC 12 reports false
// -Wmaybe-uninitialized on moving variants of vectors at -O3).
struct Block {
  enum class Kind { Heading, Paragraph, Table } kind;
  Heading heading;
  Paragraph paragraph;
  Table table;
};

struct Document {
  std::string title;
  std::vector<Block> blocks;
  void h(int level, std::string text, std::string anchor = {}) {
    blocks.push_back(Block{Block::Kind::Heading, Heading{level, std::move(text), std::move(anchor)}, {}, {}});
  }
  void p(std::vector<Text> parts) {
    blocks.push_back(Block{Block::Kind::Paragraph, {}, Paragraph{std::move(parts)}, {}});
  }
  void p(std::string text) { p(std::vector<Text>{plain(std::move(text))}); }
  void table(Table t) { blocks.push_back(Block{Block::Kind::Table, {}, {}, std::move(t)}); }
};

// Counts over the matrix that the size-and-usage section and the JSON share.
struct Statistics {
  std::map<std::string, int> by_type, by_function, by_input, by_time, by_bad_quality,
      by_effect_function;
  int cause_tags = 0, effect_tags = 0, bypass_tags = 0, inhibit_tags = 0, reset_tags = 0,
      effect_bypass_tags = 0, internal_refs = 0, xoon_effects = 0, noted_intersections = 0;
  std::size_t external_inputs = 0;
  std::set<int> first_out_groups, sif_used;
};
Statistics statistics(const model::Matrix& m);

// The document of the Markdown and HTML forms.
Document build(const model::Matrix& m, const std::string& sig, const std::vector<model::Diagnostic>& diags);
std::string render_markdown(const Document& d);
std::string render_html(const Document& d);

// The JSON form (cemv-report/1), with the canonical matrix inside.
std::string render_json(const model::Matrix& m, const std::string& sig,
                        const std::vector<model::Diagnostic>& diags);

}  // namespace cemv::reports::config
