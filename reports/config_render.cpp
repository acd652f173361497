// The configuration report's document as Markdown and as one self-contained
// HTML file (inline CSS, no scripts, no external resources).
#include "reports/config_document.hpp"

namespace cemv::reports::config {

namespace {

std::string md_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '\\': case '`': case '*': case '_': case '[': case ']': case '<': case '>': case '|':
      case '#':
        out += '\\';
        out += c;
        break;
      case '\r': break;
      case '\n': out += "<br>"; break;
      default: out += c;
    }
  }
  return out;
}

std::string md_text(const Text& t) {
  if (t.code && !t.text.empty() && t.text.find_first_of("`|\n\r") == std::string::npos)
    return "`" + t.text + "`";
  return md_escape(t.text);
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      case '\r': break;
      case '\n': out += "<br>"; break;
      default: out += c;
    }
  }
  return out;
}

std::string html_text(const Text& t) {
  return t.code ? "<code>" + html_escape(t.text) + "</code>" : html_escape(t.text);
}

const char* kCss = R"(body{font-family:sans-serif;margin:2em;color:#111;line-height:1.4}
h1{font-size:1.6em}h2{font-size:1.3em;border-bottom:1px solid #999;margin-top:2em}h3{font-size:1.1em}
table{border-collapse:collapse;margin:0.5em 0 1em 0}
th,td{border:1px solid #999;padding:2px 6px;text-align:left;vertical-align:top}
th{background:#eee}code{font-family:monospace;background:#f4f4f4}
table.grid td,table.grid th{text-align:center;font-family:monospace;min-width:2em}
table.grid th{writing-mode:vertical-rl;transform:rotate(180deg);white-space:nowrap}
table.grid th:first-child,table.grid td:first-child{writing-mode:horizontal-tb;transform:none;text-align:left}
td.t-N{background:#fde2e2}td.t-S{background:#fbc4a0}td.t-V{background:#fff3b0}
td.t-R{background:#e3c6f5}td.t-X{background:#ff6b6b;font-weight:bold}td.t-note{background:#ddd}
p.sig code{font-size:0.9em}
@media print{body{margin:0}h2{page-break-after:avoid}}
)";

}  // namespace

std::string render_markdown(const Document& d) {
  std::string out;
  for (const auto& b : d.blocks) {
    if (b.kind == Block::Kind::Heading) {
      const Heading* h = &b.heading;
      out += std::string(static_cast<std::size_t>(h->level), '#') + " " + md_escape(h->text) + "\n\n";
    } else if (b.kind == Block::Kind::Paragraph) {
      const Paragraph* p = &b.paragraph;
      for (const auto& t : p->parts) out += md_text(t);
      out += "\n\n";
    } else {
      const Table* t = &b.table;
      out += "|";
      for (const auto& h : t->header) {
        out += ' ';
        out += md_escape(h);
        out += " |";
      }
      out += "\n|";
      for (std::size_t i = 0; i < t->header.size(); ++i) out += t->grid && i ? ":-:|" : "---|";
      out += "\n";
      for (const auto& row : t->rows) {
        out += "|";
        for (const auto& cell : row) {
          out += ' ';
          out += md_text(cell);
          out += " |";
        }
        out += "\n";
      }
      out += "\n";
    }
  }
  return out;
}

std::string render_html(const Document& d) {
  std::string out =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
      html_escape(d.title) + "</title>\n<style>\n" + kCss + "</style>\n</head>\n<body>\n";
  for (const auto& b : d.blocks) {
    if (b.kind == Block::Kind::Heading) {
      const Heading* h = &b.heading;
      std::string lvl = std::to_string(h->level);
      out += "<h" + lvl;
      if (!h->anchor.empty()) out += " id=\"" + html_escape(h->anchor) + "\"";
      out += ">" + html_escape(h->text) + "</h" + lvl + ">\n";
    } else if (b.kind == Block::Kind::Paragraph) {
      const Paragraph* p = &b.paragraph;
      out += "<p>";
      for (const auto& t : p->parts) out += html_text(t);
      out += "</p>\n";
    } else {
      const Table* t = &b.table;
      out += t->grid ? "<table class=\"grid\">\n<tr>" : "<table>\n<tr>";
      for (const auto& h : t->header) out += "<th>" + html_escape(h) + "</th>";
      out += "</tr>\n";
      for (const auto& row : t->rows) {
        out += "<tr>";
        for (const auto& cell : row)
          out += (cell.css.empty() ? std::string("<td>") : "<td class=\"" + html_escape(cell.css) + "\">") +
                 html_text(cell) + "</td>";
        out += "</tr>\n";
      }
      out += "</table>\n";
    }
  }
  out += "</body>\n</html>\n";
  return out;
}

}  // namespace cemv::reports::config
