// PLCopen TC6 XML 2.01 with ST bodies (docs/plc.md P.9).
#include <gtest/gtest.h>

#include "plc/interpreter.hpp"
#include "plc/plcopen.hpp"
#include "support.hpp"

namespace cemv::plc {
namespace {

std::string project(const std::string& pous, const std::string& instances = "") {
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"                                    // 1
         "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"\n"                         // 2
         "         xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">\n"                         // 3
         "  <fileHeader companyName=\"x\" productName=\"y\" productVersion=\"1\" creationDateTime=\"2024-01-01T00:00:00\"/>\n"  // 4
         "  <contentHeader name=\"tank\"><coordinateInfo/></contentHeader>\n"                // 5
         "  <types><dataTypes/><pous>\n" +                                                  // 6
         pous + "  </pous></types>\n" + instances + "</project>\n";
}

const char* kMain =
    "    <pou name=\"Main\" pouType=\"program\">\n"                                          // 7
    "      <interface>\n"                                                                   // 8
    "        <inputVars><variable name=\"hh\"><type><BOOL/></type></variable></inputVars>\n"  // 9
    "        <outputVars><variable name=\"trip\"><type><BOOL/></type>\n"                     // 10
    "          <initialValue><simpleValue value=\"TRUE\"/></initialValue></variable></outputVars>\n"  // 11
    "        <localVars><variable name=\"t\"><type><derived name=\"TON\"/></type></variable></localVars>\n"  // 12
    "        <localVars constant=\"true\"><variable name=\"D\"><type><TIME/></type>\n"       // 13
    "          <initialValue><simpleValue value=\"T#200ms\"/></initialValue></variable></localVars>\n"  // 14
    "      </interface>\n"                                                                  // 15
    "      <body><ST><xhtml:p><![CDATA[t(IN := hh, PT := D);\n"                             // 16
    "trip := NOT t.Q;]]></xhtml:p></ST></body>\n"                                           // 17
    "    </pou>\n";

const char* kTask =
    "  <instances><configurations><configuration name=\"C\"><resource name=\"R\">\n"
    "    <task name=\"T\" interval=\"T#100ms\" priority=\"0\"><pouInstance name=\"I\" typeName=\"Main\"/></task>\n"
    "  </resource></configuration></configurations></instances>\n";

TEST(PlcOpen, ReadsPousInterfacesBodiesAndTheTask) {
  const Program p = parse_plcopen(project(kMain, kTask), "tank.xml");
  ASSERT_EQ(p.pous.size(), 1u);
  const Pou& pou = p.pous[0];
  EXPECT_EQ(pou.name, "Main");
  ASSERT_EQ(pou.variables.size(), 4u);
  EXPECT_EQ(pou.variables[1].initial, (Literal{Type::Bool, 1, 0}));
  EXPECT_EQ(pou.variables[2].type.block, StandardBlock::Ton);
  EXPECT_EQ(pou.variables[3].section, Section::Constant);
  EXPECT_EQ(p.scan_time_ms, 100);
  ASSERT_EQ(pou.body.size(), 2u);
  // the ST lines placed in the XML file
  EXPECT_EQ(pou.body[0].position, (Position{16, 35}));
  EXPECT_EQ(pou.body[1].position, (Position{17, 1}));
  Interpreter run(p);
  run.step({{"hh", Value{Type::Bool, 1, 0}}}, *p.scan_time_ms);
  run.step({}, *p.scan_time_ms);
  EXPECT_TRUE(run.value("trip").integer);
  run.step({}, *p.scan_time_ms);
  EXPECT_FALSE(run.value("trip").integer);
}

TEST(PlcOpen, ErrorsInTheBodyAtTheirXmlLine) {
  std::string pou = kMain;
  pou.replace(pou.find("trip := NOT"), 4, "tirp");
  const formats::LoadIssue issue = test::refusal(project(pou), "prog.st");
  EXPECT_EQ(issue.line, 17u);
  EXPECT_EQ(issue.column, 1u);
  EXPECT_NE(issue.what.find("undeclared variable 'tirp'"), std::string::npos) << issue.what;
}

TEST(PlcOpen, NonStBodiesRefusedAtTheirElement) {
  for (const char* lang : {"LD", "FBD", "SFC", "IL"}) {
    std::string pou = kMain;
    const std::size_t at = pou.find("<ST>");
    pou.replace(at, pou.find("</ST>") + 5 - at, std::string("<") + lang + "/>");
    const formats::LoadIssue issue = test::refusal(project(pou));
    EXPECT_EQ(issue.line, 16u) << lang;
    EXPECT_EQ(issue.column, 13u) << lang;
    EXPECT_NE(issue.what.find(std::string("a body in ") + lang + " is not in the subset"), std::string::npos)
        << issue.what;
  }
}

TEST(PlcOpen, RefusesWhatTheSubsetDoesNotCover) {
  struct Case {
    std::string from, to, words;
  };
  for (const Case& c : {
           Case{"pouType=\"program\"", "pouType=\"function\"", "pouType 'function'"},
           Case{"<BOOL/></type></variable></inputVars>", "<string/></type></variable></inputVars>", "type 'string'"},
           Case{"<derived name=\"TON\"/>", "<derived name=\"CTU\"/>", "standard block 'CTU'"},
           Case{"</inputVars>", "</inputVars><tempVars/>", "variable list <tempVars>"},
           Case{"<variable name=\"hh\">", "<variable name=\"hh\" address=\"%IX0.0\">", "located variable"},
           Case{"<simpleValue value=\"TRUE\"/>", "<arrayValue/>", "only a <simpleValue>"},
           Case{"trip := NOT t.Q;", "{attribute 'x'} trip := NOT t.Q;", "pragma"},
           Case{"<localVars>", "<localVars retain=\"true\">", "retain"},
       }) {
    std::string pou = kMain;
    ASSERT_NE(pou.find(c.from), std::string::npos) << c.from;
    pou.replace(pou.find(c.from), c.from.size(), c.to);
    const formats::LoadIssue issue = test::refusal(project(pou));
    EXPECT_NE(issue.what.find(c.words), std::string::npos) << issue.message();
    EXPECT_GT(issue.line, 6u) << issue.message();
  }
}

TEST(PlcOpen, RefusesOtherNamespacesAndBadXml) {
  std::string text = project(kMain);
  text.replace(text.find("tc6_0201"), 8, "tc6_0200");
  EXPECT_NE(test::refusal(text).what.find("is not PLCopen TC6 XML 2.01"), std::string::npos);
  EXPECT_NE(test::refusal("<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"><types>").what.find("not well-formed"),
            std::string::npos);
  std::string two = project(kMain, kTask);
  two.replace(two.find("</resource>"), 0,
              "<task name=\"U\" interval=\"T#50ms\" priority=\"1\"/>");
  EXPECT_NE(test::refusal(two).what.find("different intervals"), std::string::npos);
}

}  // namespace
}  // namespace cemv::plc
