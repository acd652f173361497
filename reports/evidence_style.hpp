// The evidence report's style: fixed fonts, line heights and table
// geometry, which the page layout (evidence_pages.hpp) counts on; colours
// after the manual's online view (10.6.1). Internal to reports/evidence*.cpp.
#pragma once

#include <cstdio>
#include <string>

namespace cemv::reports::evidence_detail {

inline constexpr const char* kEvidenceCss = R"(
body{font-family:"DejaVu Sans",Arial,Helvetica,sans-serif;font-size:9pt;line-height:1.3;color:#111827;margin:0}
h1{font-size:20pt;margin:6mm 0 2mm}h2{font-size:14pt;border-bottom:0.5mm solid #1f2937;margin:0 0 3mm;line-height:1.3}
h3{font-size:11.5pt;margin:4.5mm 0 1.5mm;line-height:1.3}p{margin:0 0 2mm}.subtitle{font-size:13pt;margin:0 0 5mm}
table{border-collapse:collapse;margin:0 0 1.5mm}table.fixed{table-layout:fixed}
th,td{border:0.2mm solid #9ca3af;padding:0.5mm 1mm;vertical-align:top;text-align:left;overflow-wrap:anywhere;line-height:1.3}
th{background:#f3f4f6;font-weight:bold}td.key{background:#f9fafb;font-weight:bold}.num{text-align:right}
.mono,pre{font-family:"DejaVu Sans Mono",monospace}
pre{white-space:pre-wrap;overflow-wrap:anywhere;font-size:7.5pt;line-height:1.3;background:#f9fafb;border:0.2mm solid #e5e7eb;padding:1mm;margin:0 0 1.5mm}
.ok{background:#dcfce7}.bad{background:#fee2e2}.warn{background:#fef3c7}.unk{background:#e5e7eb}
p.ok,p.bad,p.warn,p.unk{padding:1mm}.desc{font-style:italic}p.caption{font-size:8.5pt;font-weight:bold}
.banner{background:#fee2e2;border:0.6mm solid #dc2626;padding:2mm;font-weight:bold;font-size:11pt}
.signfield{height:9mm}
table.toc{border:none;width:186mm}table.toc td{border:none;padding:0.6mm 1mm}table.toc td.pg{text-align:right;width:14mm}
table.toc td.n{width:14mm}table.toc tr.l1 td{font-weight:bold;padding-top:2mm}table.toc tr.l2 td:nth-child(2){padding-left:6mm}
table.grid td,table.grid th{text-align:center;padding:0.3mm 0.4mm;font-size:7pt;line-height:1.25}
table.grid td.cause,table.grid th.cause{text-align:left}
table.grid th.effect{vertical-align:bottom;height:24mm;padding:0}
table.grid th.effect div{writing-mode:vertical-rl;transform:rotate(180deg);white-space:nowrap;margin:0 auto}
.t-N{background:#dbeafe}.t-S{background:#fecaca}.t-V{background:#fed7aa}.t-R{background:#bbf7d0}
.t-X,.comment{background:#e5e7eb;color:#6b7280}.t-Note{color:#6b7280}
td.support{outline:0.6mm solid #15803d;outline-offset:-0.6mm;font-weight:bold}
.defeat1{background:#fde68a}
td.traced{outline:0.6mm solid #dc2626;outline-offset:-0.6mm;font-weight:bold}
td.support.traced{outline:0.6mm dashed #dc2626}
.a-accepted{background:#86efac}.a-deviation{background:#f87171;font-weight:bold}.a-not-tested{background:#fde68a}
.legend span{display:inline-block;padding:0 1.5mm;margin-right:1.5mm;border:0.2mm solid #9ca3af}
img.diagram{display:block;border:0.2mm solid #d1d5db;margin:0 0 1.5mm}
.pagehead,.pagefoot{font-size:8pt;color:#4b5563;padding:2mm 12mm}
@media screen{body{background:#e5e7eb}
 section.sheet{width:186mm;min-height:258mm;margin:6mm auto;padding:16mm 12mm;background:#fff;box-shadow:0 0 2mm #9ca3af}}
@media print{
 @page{size:A4;margin:16mm 12mm 16mm 12mm}
 .screen{display:none}
 section.sheet{break-after:page}section.sheet:last-of-type{break-after:auto}
 tr,img,pre{break-inside:avoid}
}
)";

// The header and footer of every printed page, in the page margins (CSS
// paged media margin boxes), so they never cover the text.
inline std::string css_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f || c == '<') {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\%X ", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

inline std::string page_boxes(const std::string& stamp) {
  const char* box = "font-family:\"DejaVu Sans\",Arial,Helvetica,sans-serif;font-size:7pt;color:#4b5563;";
  return std::string("@media print{@page{\n @top-left{content:") + css_string("Evidence report · " + stamp) + ";" +
         box + "vertical-align:bottom;padding-bottom:3mm}\n @bottom-left{content:" + css_string(stamp) + ";" + box +
         "vertical-align:top;padding-top:3mm}\n @bottom-right{content:\"page \" counter(page) \" of \" counter(pages);" +
         box + "vertical-align:top;padding-top:3mm;white-space:nowrap}}}\n";
}

}  // namespace cemv::reports::evidence_detail
