// The configuration report of 11.4 (docs/reports.md).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "formats/matrix_json.hpp"
#include "reports/config_report.hpp"
#include "model/validate.hpp"
#include "tests/formats/test_csv_support.hpp"

namespace cemv::reports {

using namespace cemv::model;
using namespace cemv::formats;
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

Matrix sample() { return parse_matrix(to_canonical_json(testing::every_field_matrix())); }

TEST(ReportFormat, Names) {
  EXPECT_EQ(report_format_from_string("md"), ReportFormat::Markdown);
  EXPECT_EQ(report_format_from_string("html"), ReportFormat::Html);
  EXPECT_EQ(report_format_from_string("json"), ReportFormat::Json);
  EXPECT_FALSE(report_format_from_string("pdf").has_value());
}

TEST(Report, MarkdownHasEverySectionAndTheSignatureTopAndBottom) {
  const Matrix m = sample();
  const std::string md = configuration_report(m, ReportFormat::Markdown);
  const std::string sig = signature(m);
  EXPECT_EQ(count(md, sig), 2u);
  EXPECT_LT(md.find(sig), md.find("## 1 Properties"));
  EXPECT_GT(md.rfind(sig), md.find("## 8 Intersections"));
  for (const char* section : {"# Configuration report: RT\\_ALL", "## 1 Properties", "## 2 Size and usage",
                              "## 3 Validation summary", "## 4 SIF groups", "## 5 First-out groups",
                              "## 6 Causes", "## 7 Effects", "## 8 Intersections", "## 9 User notes",
                              "## Signature"})
    EXPECT_NE(md.find(section), std::string::npos) << section;
  // Every cause and effect has its own detail section, every intersection a row.
  for (const auto& c : m.causes)
    EXPECT_NE(md.find("### Cause " + std::to_string(c.id) + ": "), std::string::npos) << c.id;
  for (const auto& e : m.effects)
    EXPECT_NE(md.find("### Effect " + std::to_string(e.id) + ": "), std::string::npos) << e.id;
  // Fields in detail, with their values.
  EXPECT_NE(md.find("| `analog.prewarning` | 0.05 | 6.3.5 |"), std::string::npos);
  EXPECT_NE(md.find("| `override.max_s` | 600 |"), std::string::npos);
  EXPECT_NE(md.find("| `process_data.mask_tag` | `XV_101_MASK` |"), std::string::npos);
  EXPECT_NE(md.find("| `inhibit_tag` | `INH 100` |"), std::string::npos);
  // Usage against the limits of 3.4, and the per-type counts.
  EXPECT_NE(md.find("| Causes (rows) | 5 | 128 |"), std::string::npos);
  EXPECT_NE(md.find("| Intersections | 8 | 1024 |"), std::string::npos);
  EXPECT_NE(md.find("| `V` | overridable | 3 |"), std::string::npos);
  EXPECT_NE(md.find("| `2oo3` | 1 |"), std::string::npos);
  EXPECT_NE(md.find("| `on_delay` | 1 |"), std::string::npos);
  EXPECT_NE(md.find("| `analog` | 2 |"), std::string::npos);
  // The grid shows XooN; the SIF and first-out groups list their members.
  EXPECT_NE(md.find("V 2oo3+"), std::string::npos);
  EXPECT_NE(md.find("| 64 | Last | 3 REF\\_OR | none |"), std::string::npos);
  EXPECT_NE(md.find("| 15 | 4 LT\\_LOW |"), std::string::npos);
  // User notes (11.4) in one list.
  EXPECT_NE(md.find("| intersection cause 4 / effect 2 | (2) |"), std::string::npos);
  // Markdown-significant characters in free text are escaped, not interpreted.
  EXPECT_NE(md.find("| Pressure \"PT\"; trip |"), std::string::npos);
  EXPECT_NE(md.find("Tank level high-high, \"A\"; B"), std::string::npos);
}

TEST(Report, ValidationSummaryCountsTheFindings) {
  const Matrix m = sample();
  const auto diags = validate(m);
  std::size_t errors = 0, warnings = 0;
  for (const auto& d : diags) (d.severity == Severity::Error ? errors : warnings)++;
  ASSERT_GT(errors, 0u);  // the X intersection at least
  const std::string md = configuration_report(m, ReportFormat::Markdown);
  EXPECT_NE(md.find(std::to_string(errors) + " error(s), " + std::to_string(warnings) + " warning(s)"),
            std::string::npos);
  for (const auto& d : diags) EXPECT_NE(md.find(d.rule), std::string::npos) << d.rule;
}

TEST(Report, HtmlIsOneSelfContainedEscapedFile) {
  Matrix m = sample();
  m.causes[1].description = "<script>alert('x')</script> & \"more\"";
  m.effects[0].note = "<img src=http://example.com/x.png>";
  const std::string html = configuration_report(m, ReportFormat::Html);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<style>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  // The only "src=" and "http" are the escaped text of the note (in the effect's
  // field table and in the list of user notes).
  EXPECT_EQ(count(html, "src="), count(html, "&lt;img src=http://"));
  EXPECT_EQ(count(html, "http"), count(html, "&lt;img src=http://"));
  EXPECT_NE(html.find("&lt;img src=http://example.com/x.png&gt;"), std::string::npos);
  EXPECT_EQ(html.find("href="), std::string::npos);
  EXPECT_EQ(html.find("url("), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;more&quot;"), std::string::npos);
  EXPECT_EQ(count(html, signature(m)), 2u);
  // The C&E grid is a table with the type in its cells.
  EXPECT_NE(html.find("<table class=\"grid\">"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"t-X\">X</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"t-R\">R+</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"t-note\">*+</td>"), std::string::npos);
  // Balanced tables.
  EXPECT_EQ(count(html, "<table"), count(html, "</table>"));
  EXPECT_EQ(count(html, "<tr>"), count(html, "</tr>"));
}

TEST(Report, JsonIsMachineReadableWithAFixedKeyOrder) {
  const Matrix m = sample();
  const std::string text = configuration_report(m, ReportFormat::Json);
  const auto j = nlohmann::ordered_json::parse(text);
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  // The sample has validation errors (an X intersection): the banner says so.
  EXPECT_EQ(keys, (std::vector<std::string>{"format", "report", "signature", "banner", "properties",
                                            "statistics", "validation", "sif_groups", "first_out_groups",
                                            "grid", "matrix", "signature_end"}));
  EXPECT_EQ(j["signature"], signature(m));
  EXPECT_EQ(j["signature_end"], signature(m));
  EXPECT_EQ(j["statistics"]["intersection_types"]["V"], 3);
  EXPECT_EQ(j["statistics"]["intersection_types"]["*"], 1);
  EXPECT_EQ(j["statistics"]["causes"]["configured"], 5);
  EXPECT_EQ(j["statistics"]["cause_inputs"]["analog"], 2);
  EXPECT_EQ(j["grid"]["rows"][0]["cells"], "VN.");
  // The matrix section is the canonical form itself: every field of every element.
  EXPECT_EQ(nlohmann::json::parse(text)["matrix"], nlohmann::json::parse(to_canonical_json(m)));
  EXPECT_EQ(j["matrix"]["causes"][0]["analog"]["limit"].dump(), "0.1");
}

TEST(Report, DeterministicInEveryFormat) {
  for (auto f : {ReportFormat::Markdown, ReportFormat::Html, ReportFormat::Json}) {
    const std::string a = configuration_report(sample(), f);
    const std::string b = configuration_report(sample(), f);
    EXPECT_EQ(a, b);
  }
}

TEST(Report, EmptyMatrixStillHasEverySection) {
  Matrix m;
  m.name = "EMPTY";
  const std::string md = configuration_report(m, ReportFormat::Markdown);
  EXPECT_NE(md.find("No causes."), std::string::npos);
  EXPECT_NE(md.find("No intersections."), std::string::npos);
  EXPECT_NE(md.find("No safety instrumented function groups"), std::string::npos);
  EXPECT_EQ(count(md, signature(m)), 2u);
}

}  // namespace
}  // namespace cemv::reports
