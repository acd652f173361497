#include "plc/plcopen.hpp"

#include <pugixml.hpp>

#include "formats/diagnostics.hpp"
#include "model/text.hpp"
#include "plc/check.hpp"
#include "plc/lexer.hpp"
#include "plc/parser.hpp"

namespace cemv::plc {

namespace {

// An element's local name (`xhtml:p` is `p`).
std::string_view local(const pugi::xml_node& n) {
  std::string_view name = n.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

class Reader {
 public:
  Reader(std::string text, std::string file) : text_(std::move(text)), file_(std::move(file)), lines_(text_) {}

  Program run() {
    pugi::xml_document doc;
    const pugi::xml_parse_result r =
        doc.load_buffer(text_.data(), text_.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!r) fail_at(static_cast<std::size_t>(r.offset), std::string("not well-formed XML: ") + r.description());
    const pugi::xml_node project = doc.document_element();
    if (local(project) != "project") fail(project, "the root element is not a PLCopen <project>");
    const std::string_view ns = project.attribute("xmlns").value();
    if (ns != kPlcopenNamespace)
      fail(project, "namespace " + model::in_quotes(ns) + " is not PLCopen TC6 XML 2.01 (" +
                        std::string(kPlcopenNamespace) + "; docs/plc.md P.9)");
    Program program;
    program.file = file_;
    for (pugi::xml_node child : project.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string_view n = local(child);
      if (n == "types") types(child, program);
      else if (n == "instances") instances(child, program);
      else if (n != "fileHeader" && n != "contentHeader" && n != "addData" && n != "documentation")
        refused(child);
    }
    if (program.pous.empty()) fail(project, "no POU in the project");
    check_program(program);
    return program;
  }

 private:
  std::string text_;
  std::string file_;
  formats::LineIndex lines_;

  Position position(const pugi::xml_node& n) const {
    std::ptrdiff_t off = n.offset_debug();
    if (off < 0) return {};
    if (n.type() == pugi::node_element && off > 0) --off;  // at its '<', not its name
    auto [line, column] = lines_.line_and_column(static_cast<std::size_t>(off));
    return {line, column};
  }
  [[noreturn]] void fail(const pugi::xml_node& n, std::string what) const { refuse(file_, position(n), std::move(what)); }
  [[noreturn]] void fail_at(std::size_t offset, std::string what) const {
    auto [line, column] = lines_.line_and_column(offset);
    refuse(file_, {line, column}, std::move(what));
  }
  [[noreturn]] void refused(const pugi::xml_node& n) const {
    fail(n, "element <" + std::string(n.name()) + "> is not in the subset (docs/plc.md P.9)");
  }

  void types(const pugi::xml_node& types, Program& program) {
    for (pugi::xml_node child : types.children()) {
      if (child.type() != pugi::node_element) continue;
      if (local(child) == "dataTypes") {
        if (pugi::xml_node t = child.find_child([](pugi::xml_node c) { return c.type() == pugi::node_element; }))
          fail(t, "user-defined data types are not in the subset (docs/plc.md P.2)");
      } else if (local(child) == "pous") {
        for (pugi::xml_node pou : child.children())
          if (pou.type() == pugi::node_element) program.pous.push_back(read_pou(pou));
      } else {
        refused(child);
      }
    }
  }

  Pou read_pou(const pugi::xml_node& node) {
    if (local(node) != "pou") refused(node);
    Pou pou;
    pou.position = position(node);
    pou.name = node.attribute("name").value();
    const std::string_view type = node.attribute("pouType").value();
    if (type == "program") pou.kind = PouKind::Program;
    else if (type == "functionBlock") pou.kind = PouKind::FunctionBlock;
    else fail(node, "pouType " + model::in_quotes(type) + " is not in the subset: program or functionBlock (docs/plc.md P.1)");
    if (pou.name.empty()) fail(node, "a <pou> without a name");
    bool has_body = false;
    for (pugi::xml_node child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string_view n = local(child);
      if (n == "interface") interface(child, pou);
      else if (n == "body") {
        if (has_body) fail(child, "a POU with more than one <body>");
        has_body = true;
        pou.body = body(child);
      } else if (n == "addData") vendor_data(child);
      else if (n != "documentation") refused(child);
    }
    if (!has_body) fail(node, "POU " + model::in_quotes(pou.name) + " has no <body>");
    return pou;
  }

  // Vendor data can carry program parts (methods, actions): refused, but for
  // the object ids CODESYS gives every element.
  void vendor_data(const pugi::xml_node& add) {
    for (pugi::xml_node d : add.children()) {
      if (d.type() != pugi::node_element) continue;
      const std::string_view name = d.attribute("name").value();
      if (name != "http://www.3s-software.com/plcopenxml/objectid")
        fail(d, "vendor data " + model::in_quotes(name) + " is not read; cemv cannot tell what it adds to the program (docs/plc.md P.9)");
    }
  }

  void interface(const pugi::xml_node& node, Pou& pou) {
    for (pugi::xml_node list : node.children()) {
      if (list.type() != pugi::node_element) continue;
      const std::string_view n = local(list);
      Section section;
      if (n == "inputVars") section = Section::Input;
      else if (n == "outputVars") section = Section::Output;
      else if (n == "inOutVars") section = Section::InOut;
      else if (n == "localVars") section = Section::Local;
      else if (n == "addData") { vendor_data(list); continue; }
      else if (n == "documentation") continue;
      else fail(list, "variable list <" + std::string(n) + "> is not in the subset (docs/plc.md P.3)");
      if (list.attribute("constant").as_bool()) {
        if (section != Section::Local) fail(list, "constant=\"true\" on <" + std::string(n) + "> is not in the subset (docs/plc.md P.3)");
        section = Section::Constant;
      }
      for (const char* q : {"retain", "nonretain", "persistent", "nonpersistent"})
        if (list.attribute(q).as_bool()) fail(list, std::string(q) + "=\"true\" is not in the subset (docs/plc.md P.3)");
      for (pugi::xml_node v : list.children()) {
        if (v.type() != pugi::node_element) continue;
        if (local(v) == "addData") { vendor_data(v); continue; }
        if (local(v) == "documentation") continue;
        if (local(v) != "variable") refused(v);
        pou.variables.push_back(variable(v, section));
      }
    }
  }

  Variable variable(const pugi::xml_node& node, Section section) {
    Variable v;
    v.position = position(node);
    v.section = section;
    v.name = node.attribute("name").value();
    if (v.name.empty()) fail(node, "a <variable> without a name");
    if (node.attribute("address")) fail(node, "located variable (address) is not in the subset (docs/plc.md P.3)");
    pugi::xml_node type;
    for (pugi::xml_node child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string_view n = local(child);
      if (n == "type") type = child;
      else if (n == "initialValue") initial(child, v);
      else if (n == "addData") vendor_data(child);
      else if (n != "documentation") refused(child);
    }
    if (!type) fail(node, "variable " + model::in_quotes(v.name) + " has no <type>");
    pugi::xml_node t = type.find_child([](pugi::xml_node c) { return c.type() == pugi::node_element; });
    if (!t) fail(type, "an empty <type>");
    const std::string name = local(t) == "derived" ? t.attribute("name").value() : std::string(local(t));
    v.type = parse_type_name(name, file_, position(t));
    if (v.initial && v.type.kind != VarType::Kind::Elementary)
      fail(node, "an initial value of a block instance is not in the subset (docs/plc.md P.3)");
    return v;
  }

  void initial(const pugi::xml_node& node, Variable& v) {
    pugi::xml_node simple = node.child("simpleValue");
    if (!simple) {
      pugi::xml_node other = node.find_child([](pugi::xml_node c) { return c.type() == pugi::node_element; });
      fail(other ? other : node, "only a <simpleValue> initial value is in the subset (docs/plc.md P.3)");
    }
    const Position at = position(simple);
    Position where;
    v.initial = parse_initial_value(simple.attribute("value").value(), Origin{file_, at.line, at.column}, where);
    v.initial_position = at;
  }

  std::vector<Statement> body(const pugi::xml_node& node) {
    pugi::xml_node lang = node.find_child([](pugi::xml_node c) { return c.type() == pugi::node_element && local(c) != "documentation" && local(c) != "addData"; });
    if (!lang) fail(node, "an empty <body>");
    if (local(lang) != "ST")
      fail(lang, "a body in " + std::string(local(lang)) + " is not in the subset: only ST is read (docs/plc.md P.9)");
    // the text: in <xhtml:p> (the schema's formatted text) or directly in <ST>
    pugi::xml_node holder = lang;
    if (pugi::xml_node p = lang.find_child([](pugi::xml_node c) { return c.type() == pugi::node_element; })) {
      if (local(p) != "p") refused(p);
      holder = p;
    }
    std::vector<Statement> out;
    for (pugi::xml_node t : holder.children()) {
      if (t.type() == pugi::node_element) refused(t);
      if (t.type() != pugi::node_pcdata && t.type() != pugi::node_cdata) continue;
      const Position at = position(t);
      auto part = parse_statements(t.value(), Origin{file_, at.line, at.column});
      out.insert(out.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
    }
    return out;
  }

  // The scan time: the interval of the cyclic task (P.9).
  void instances(const pugi::xml_node& node, Program& program) {
    for (pugi::xpath_node x : node.select_nodes(".//*[local-name()='task']")) {
      const pugi::xml_node task = x.node();
      const pugi::xml_attribute interval = task.attribute("interval");
      if (!interval) fail(task, "a task without an interval (an event task) is not in the subset (docs/plc.md P.9)");
      const Position at = position(task);
      const auto tokens = tokenize(interval.value(), Origin{file_, at.line, at.column});
      if (tokens.size() != 2 || tokens[0].kind != Tok::Time || tokens[0].integer <= 0)
        fail(task, "task interval " + model::in_quotes(interval.value()) + " is not a positive TIME literal such as T#100ms");
      if (program.scan_time_ms && *program.scan_time_ms != tokens[0].integer)
        fail(task, "tasks with different intervals: cemv checks a program on one cyclic task (docs/plc.md P.9)");
      program.scan_time_ms = tokens[0].integer;
    }
    for (pugi::xpath_node x : node.select_nodes(".//*[local-name()='globalVars' or local-name()='accessVars']"))
      fail(x.node(), "<" + std::string(local(x.node())) + "> is not in the subset (docs/plc.md P.3)");
  }
};

std::string normalized_line_ends(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r') {
      out += '\n';
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

}  // namespace

Program parse_plcopen(std::string_view text, const std::string& file) {
  // CR LF as LF first, so pugixml's offsets stay those of the lines (P.9)
  return Reader(normalized_line_ends(text), file).run();
}

}  // namespace cemv::plc
