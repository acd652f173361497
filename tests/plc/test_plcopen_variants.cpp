// PLCopen XML as exporters write it, generated from seeded random programs
// (docs/plc.md P.9): bodies in CDATA or as escaped text, in <xhtml:p> or
// directly in <ST>, CR LF or LF line ends, documentation and CODESYS object
// ids beside the program, the task interval in several spellings. Each file
// reads back as the program it was written from.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "formats/diagnostics.hpp"
#include "plc/check.hpp"
#include "plc/plcopen.hpp"
#include "plc/print.hpp"
#include "random_program.hpp"

namespace cemv::plc {
namespace {

struct Variant {
  bool cdata, xhtml_p, crlf, documentation, object_ids;
  int interval;
};

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

std::string type_element(const VarType& t) {
  switch (t.kind) {
    case VarType::Kind::Elementary: return "<" + std::string(type_name(t.type)) + "/>";
    case VarType::Kind::Standard: return "<derived name=\"" + std::string(block_name(t.block)) + "\"/>";
    case VarType::Kind::User: return "<derived name=\"" + t.user + "\"/>";
  }
  return "";
}

std::string list_element(Section s) {
  switch (s) {
    case Section::Input: return "inputVars";
    case Section::Output: return "outputVars";
    case Section::InOut: return "inOutVars";
    default: return "localVars";
  }
}

std::string pou_xml(const Pou& pou, const Variant& v) {
  std::string out = "    <pou name=\"" + pou.name + "\" pouType=\"" +
                    (pou.kind == PouKind::Program ? "program" : "functionBlock") + "\">\n";
  if (v.documentation) out += "      <documentation><xhtml:p>Written from the C&amp;E sheet.</xhtml:p></documentation>\n";
  out += "      <interface>\n";
  for (std::size_t i = 0; i < pou.variables.size();) {
    const Section s = pou.variables[i].section;
    const std::string list = list_element(s);
    out += "        <" + list + (s == Section::Constant ? " constant=\"true\"" : "") + ">\n";
    for (; i < pou.variables.size() && pou.variables[i].section == s; ++i) {
      const Variable& var = pou.variables[i];
      out += "          <variable name=\"" + var.name + "\"><type>" + type_element(var.type) + "</type>";
      if (var.initial) out += "<initialValue><simpleValue value=\"" + literal_text(*var.initial) + "\"/></initialValue>";
      if (v.documentation) out += "<documentation><xhtml:p>tag</xhtml:p></documentation>";
      out += "</variable>\n";
    }
    out += "        </" + list + ">\n";
  }
  out += "      </interface>\n      <body>\n        <ST>";
  std::string text;
  for (const Statement& s : pou.body) text += print_statement(s, 2);
  text = v.cdata ? "<![CDATA[" + text + "]]>" : escaped(text);
  out += v.xhtml_p ? "<xhtml:p>" + text + "</xhtml:p>" : text;
  out += "</ST>\n      </body>\n";
  if (v.object_ids)
    out += "      <addData><data name=\"http://www.3s-software.com/plcopenxml/objectid\" handleUnknown=\"discard\">"
           "<ObjectId>6f1c</ObjectId></data></addData>\n";
  return out + "    </pou>\n";
}

std::string project_xml(const Program& p, const Variant& v) {
  static const char* kIntervals[] = {"T#100ms", "t#100MS", "TIME#0.1s", "T#100ms"};
  std::string out =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n"
      "  <fileHeader companyName=\"c\" productName=\"p\" productVersion=\"1\" creationDateTime=\"2024-01-01T00:00:00\"/>\n"
      "  <contentHeader name=\"random\"><coordinateInfo><fbd><scaling x=\"1\" y=\"1\"/></fbd></coordinateInfo></contentHeader>\n"
      "  <types>\n    <dataTypes/>\n    <pous>\n";
  for (const Pou& pou : p.pous) out += pou_xml(pou, v);
  out += "    </pous>\n  </types>\n  <instances><configurations><configuration name=\"Config\"><resource name=\"Res\">\n"
         "    <task name=\"Main_task\" interval=\"" + std::string(kIntervals[v.interval]) + "\" priority=\"1\">"
         "<pouInstance name=\"Main_instance\" typeName=\"Main\"/></task>\n"
         "  </resource></configuration></configurations></instances>\n</project>\n";
  if (!v.crlf) return out;
  std::string crlf;
  for (char c : out) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  return crlf;
}

TEST(PlcOpenVariants, RandomProgramsReadBackFromEachVariant) {
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    Program p = test::Generator(seed).program();
    p.file = "random.st";
    check_program(p);
    std::mt19937_64 rng(seed);
    const Variant v{rng() % 2 == 0, rng() % 3 != 0, rng() % 2 == 0, rng() % 2 == 0, rng() % 2 == 0,
                    static_cast<int>(rng() % 4)};
    const std::string xml = project_xml(p, v);
    Program back;
    try {
      back = parse_plcopen(xml, "random.xml");
    } catch (const formats::LoadError& e) {
      FAIL() << "seed " << seed << ": " << e.issues()[0].message() << "\n" << xml;
    }
    EXPECT_EQ(back.scan_time_ms, 100) << "seed " << seed;
    back.scan_time_ms.reset();
    ASSERT_EQ(without_positions(back), without_positions(p)) << "seed " << seed << "\n" << xml;
    // the body's first statement placed at its line and column in the XML file
    const std::size_t st = xml.find("<ST>", xml.find("pouType=\"program\""));
    const std::size_t line_start = xml.rfind('\n', st) + 1;
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(st), '\n'));
    const std::size_t column = st - line_start + 1 + 4 + (v.xhtml_p ? 9 : 0) + (v.cdata ? 9 : 0) + 2;
    EXPECT_EQ(back.pous[1].body[0].position, (Position{line, column})) << "seed " << seed;
  }
}

}  // namespace
}  // namespace cemv::plc
