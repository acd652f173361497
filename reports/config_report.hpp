// The configuration report of 11.4 (docs/reports.md): properties, size and usage
// statistics, every cause, effect and intersection in detail, SIF and first-out
// groups, the validation summary (11.5) and the matrix signature at the top and
// the bottom, so a printed report ties to one exact matrix version.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "model/matrix.hpp"

namespace cemv::reports {

enum class ReportFormat { Markdown, Html, Json };

// "md", "html", "json"; nullopt otherwise.
std::optional<ReportFormat> report_format_from_string(std::string_view name);

// The whole report as text. Deterministic: no time stamps, no host data, every
// list in id order; the HTML form is one self-contained file (inline CSS, no
// scripts, no external resources); the JSON form has a fixed key order.
std::string configuration_report(const model::Matrix& m, ReportFormat format);

}  // namespace cemv::reports
