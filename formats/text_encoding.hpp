// The character encoding of text inputs: every text cemv reads is UTF-8, and
// a file that is not is refused at its first bad byte, never read as garbled
// text; a spreadsheet saved in the Windows ANSI code page can be read as
// Windows-1252 when the user says so (`import-csv --encoding windows-1252`).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cemv::formats {

enum class TextEncoding { Utf8, Windows1252 };

// "utf-8", "windows-1252" (and the aliases "utf8", "cp1252", "latin-1"...);
// nullopt for another name.
std::optional<TextEncoding> text_encoding_from_string(std::string_view name);
const char* to_string(TextEncoding e);  // "UTF-8", "Windows-1252"

// Byte offset of the first byte that does not belong to well-formed UTF-8
// (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF);
// nullopt when all of `text` is UTF-8.
std::optional<std::size_t> first_invalid_utf8(std::string_view text);

// The text as UTF-8. UTF-8 input is checked and returned as it is; a
// Windows-1252 input is converted byte by byte. Throws LoadError naming
// `source_name`, the line and column of the first byte that cannot be read
// (a byte that is not UTF-8, with the hint to give --encoding; one of the five
// bytes Windows-1252 leaves undefined).
std::string decode_text(std::string_view bytes, TextEncoding encoding, const std::string& source_name);

}  // namespace cemv::formats
