#include "formats/text_encoding.hpp"

#include <cstdio>

#include "formats/diagnostics.hpp"
#include "model/text.hpp"

namespace cemv::formats {

namespace {

// Windows-1252 0x80-0x9F (0 = undefined); 0xA0-0xFF are U+00A0-U+00FF.
constexpr char32_t kCp1252High[32] = {
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

std::string hex_byte(unsigned char b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", b);
  return buf;
}

[[noreturn]] void refuse(std::string_view bytes, std::size_t at, const std::string& source_name, std::string what) {
  auto [line, column] = line_and_column(bytes, at);
  LoadIssue issue{"line " + std::to_string(line) + ", column " + std::to_string(column), std::move(what), source_name};
  issue.line = line;
  issue.column = column;
  throw LoadError({issue});
}

}  // namespace

std::optional<TextEncoding> text_encoding_from_string(std::string_view name) {
  std::string n;
  for (char c : name) n += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  if (n == "utf-8" || n == "utf8") return TextEncoding::Utf8;
  if (n == "windows-1252" || n == "cp1252" || n == "latin-1" || n == "latin1" || n == "iso-8859-1")
    return TextEncoding::Windows1252;
  return std::nullopt;
}

const char* to_string(TextEncoding e) { return e == TextEncoding::Utf8 ? "UTF-8" : "Windows-1252"; }

std::optional<std::size_t> first_invalid_utf8(std::string_view s) {
  auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  auto cont = [&](std::size_t k) { return k < s.size() && (b(k) & 0xC0) == 0x80; };
  for (std::size_t i = 0; i < s.size();) {
    unsigned char c = b(i);
    std::size_t n = 0;
    if (c < 0x80) n = 1;
    else if (c >= 0xC2 && c <= 0xDF) n = cont(i + 1) ? 2 : 0;
    else if (c >= 0xE0 && c <= 0xEF) {
      n = cont(i + 1) && cont(i + 2) ? 3 : 0;
      if (n && c == 0xE0 && b(i + 1) < 0xA0) n = 0;  // overlong
      if (n && c == 0xED && b(i + 1) > 0x9F) n = 0;  // surrogates
    } else if (c >= 0xF0 && c <= 0xF4) {
      n = cont(i + 1) && cont(i + 2) && cont(i + 3) ? 4 : 0;
      if (n && c == 0xF0 && b(i + 1) < 0x90) n = 0;  // overlong
      if (n && c == 0xF4 && b(i + 1) > 0x8F) n = 0;  // beyond U+10FFFF
    }
    if (n == 0) return i;
    i += n;
  }
  return std::nullopt;
}

std::string decode_text(std::string_view bytes, TextEncoding encoding, const std::string& source_name) {
  if (encoding == TextEncoding::Utf8) {
    if (auto at = first_invalid_utf8(bytes))
      refuse(bytes, *at, source_name,
             "byte " + hex_byte(static_cast<unsigned char>(bytes[*at])) +
                 " is not UTF-8: the file is in another encoding (a spreadsheet saved as \"CSV\" in the Windows "
                 "code page is Windows-1252); give --encoding windows-1252 to read it as that, or save it as "
                 "UTF-8");
    return std::string(bytes);
  }
  std::string out;
  out.reserve(bytes.size() + bytes.size() / 8);
  std::size_t start = 0;
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF")
    refuse(bytes, 0, source_name,
           "the file starts with a UTF-8 byte-order mark, yet --encoding windows-1252 was given; leave the "
           "option out to read it as UTF-8");
  for (std::size_t i = start; i < bytes.size(); ++i) {
    auto c = static_cast<unsigned char>(bytes[i]);
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0xA0) {
      char32_t u = kCp1252High[c - 0x80];
      if (u == 0) refuse(bytes, i, source_name, "byte " + hex_byte(c) + " has no character in Windows-1252");
      append_utf8(out, u);
    } else {
      append_utf8(out, c);
    }
  }
  return out;
}

}  // namespace cemv::formats
