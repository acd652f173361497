// The program as PLCopen TC6 XML 2.01 (docs/plc.md P.9): the writer beside
// the reader, pugixml for the XML and print.hpp for the ST bodies.
#include <sstream>

#include <pugixml.hpp>

#include "plc/plcopen.hpp"
#include "plc/print.hpp"

namespace cemv::plc {

namespace {

const char* section_element(Section s) {
  switch (s) {
    case Section::Input: return "inputVars";
    case Section::Output: return "outputVars";
    case Section::InOut: return "inOutVars";
    default: return "localVars";
  }
}

void documentation(pugi::xml_node parent, const std::string& text) {
  if (text.empty()) return;
  parent.append_child("documentation").append_child("xhtml:p").append_child(pugi::node_pcdata).set_value(text.c_str());
}

void variable(pugi::xml_node list, const Variable& v) {
  pugi::xml_node x = list.append_child("variable");
  x.append_attribute("name") = v.name.c_str();
  pugi::xml_node type = x.append_child("type");
  switch (v.type.kind) {
    case VarType::Kind::Elementary: type.append_child(std::string(type_name(v.type.type)).c_str()); break;
    case VarType::Kind::Standard:
      type.append_child("derived").append_attribute("name") = std::string(block_name(v.type.block)).c_str();
      break;
    case VarType::Kind::User: type.append_child("derived").append_attribute("name") = v.type.user.c_str(); break;
  }
  if (v.initial)
    x.append_child("initialValue").append_child("simpleValue").append_attribute("value") =
        literal_text(*v.initial).c_str();
  documentation(x, v.comment);
}

void pou(pugi::xml_node pous, const Pou& p) {
  pugi::xml_node x = pous.append_child("pou");
  x.append_attribute("name") = p.name.c_str();
  x.append_attribute("pouType") = p.kind == PouKind::Program ? "program" : "functionBlock";
  pugi::xml_node iface = x.append_child("interface");
  for (std::size_t i = 0; i < p.variables.size();) {
    const Section s = p.variables[i].section;
    pugi::xml_node list = iface.append_child(section_element(s));
    if (s == Section::Constant) list.append_attribute("constant") = "true";
    for (; i < p.variables.size() && p.variables[i].section == s; ++i) variable(list, p.variables[i]);
  }
  std::string text;
  for (const Statement& s : p.body) text += print_statement(s);
  x.append_child("body").append_child("ST").append_child("xhtml:p").append_child(pugi::node_cdata).set_value(text.c_str());
  documentation(x, p.comment);
}

}  // namespace

std::string write_plcopen(const Program& program) {
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "utf-8";
  pugi::xml_node project = doc.append_child("project");
  project.append_attribute("xmlns") = std::string(kPlcopenNamespace).c_str();
  project.append_attribute("xmlns:xhtml") = "http://www.w3.org/1999/xhtml";
  pugi::xml_node header = project.append_child("fileHeader");
  header.append_attribute("companyName") = "cemv";
  header.append_attribute("productName") = "cemv export-st";
  header.append_attribute("productVersion") = "1";
  // no clock: the same program gives the same bytes
  header.append_attribute("creationDateTime") = "1970-01-01T00:00:00";
  const Pou* main = nullptr;
  for (const Pou& p : program.pous)
    if (p.kind == PouKind::Program && !main) main = &p;
  pugi::xml_node content = project.append_child("contentHeader");
  content.append_attribute("name") = main ? main->name.c_str() : "cemv";
  content.append_child("coordinateInfo");
  pugi::xml_node types = project.append_child("types");
  types.append_child("dataTypes");
  pugi::xml_node pous = types.append_child("pous");
  for (const Pou& p : program.pous) pou(pous, p);
  if (main && program.scan_time_ms) {
    pugi::xml_node resource = project.append_child("instances")
                                  .append_child("configurations")
                                  .append_child("configuration");
    resource.append_attribute("name") = "CONFIGURATION";
    resource = resource.append_child("resource");
    resource.append_attribute("name") = "RESOURCE";
    pugi::xml_node task = resource.append_child("task");
    task.append_attribute("name") = "CYCLIC";
    task.append_attribute("interval") = literal_text(Literal{Type::Time, *program.scan_time_ms, 0.0f}).c_str();
    task.append_attribute("priority") = "0";
    pugi::xml_node instance = task.append_child("pouInstance");
    instance.append_attribute("name") = "MAIN";
    instance.append_attribute("typeName") = main->name.c_str();
  }
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_indent, pugi::encoding_utf8);
  return out.str();
}

}  // namespace cemv::plc
