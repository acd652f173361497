// XML 1.0 character data, shared by the JUnit printers of `cemv check` and
// `cemv validate`, and the escaping of the HTML and SVG cemv writes.
#pragma once

#include <string>
#include <string_view>

namespace cemv::reports {

// Markup characters escaped; characters XML forbids (most controls,
// U+FFFE/U+FFFF) and invalid UTF-8 become U+FFFD, so the file always parses.
// In attributes, line breaks and tabs become character references
// (attribute-value normalisation would otherwise turn them into spaces).
std::string xml_escape(std::string_view s, bool attribute);

// The five-character escaping of generated HTML and SVG (checklists, the
// evidence report, timing diagrams, replay reports): & < > and " (text
// and attribute values alike); everything else passes through.
std::string html_escape(std::string_view s);

}  // namespace cemv::reports
