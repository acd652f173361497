// `cemv check --format junit` (docs/checker.md, "Outputs").
#pragma once

#include <string>

#include "checker/result.hpp"
#include "reports/check_report.hpp"

namespace cemv::reports {

std::string check_junit(const checker::CheckResult& r, const CheckReportInputs& in);

}  // namespace cemv::reports
