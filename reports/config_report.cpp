// The configuration report of 11.4, docs/reports.md: the document is built in
// config_sections.cpp and rendered in config_render.cpp; the JSON form is
// config_json.cpp.
#include "reports/config_report.hpp"

#include "formats/matrix_json.hpp"
#include "model/validate.hpp"
#include "reports/config_document.hpp"

namespace cemv::reports {

using namespace cemv::model;
using namespace cemv::formats;

std::optional<ReportFormat> report_format_from_string(std::string_view name) {
  if (name == "md" || name == "markdown") return ReportFormat::Markdown;
  if (name == "html") return ReportFormat::Html;
  if (name == "json") return ReportFormat::Json;
  return std::nullopt;
}

std::string configuration_report(const Matrix& m, ReportFormat format) {
  const std::string sig = signature(m);
  const std::vector<Diagnostic> diags = validate(m);
  if (format == ReportFormat::Json) return config::render_json(m, sig, diags);
  config::Document d = config::build(m, sig, diags);
  return format == ReportFormat::Html ? config::render_html(d) : config::render_markdown(d);
}

}  // namespace cemv::reports
