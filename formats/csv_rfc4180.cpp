// RFC 4180 reading and quoting, shared by cemv-csv/1 and the grid reader.
#include "formats/csv_rfc4180.hpp"

#include <utility>

#include "formats/csv_text.hpp"
#include "formats/diagnostics.hpp"

namespace cemv::formats {

using csv_text::where_of;

std::vector<CsvRecord> parse_csv(std::string_view text, char separator, bool strict,
                                 const std::string& source_name) {
  std::vector<CsvRecord> records;
  std::vector<LoadIssue> errors;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  auto error = [&](int l, int c, std::string what) {
    errors.push_back({where_of(source_name, l, c), std::move(what)});
  };
  while (i < n) {
    CsvRecord rec;
    rec.line = line;
    bool end_of_record = false;
    while (!end_of_record) {
      CsvField f;
      f.line = line;
      f.column = static_cast<int>(rec.fields.size() + 1);
      if (i < n && text[i] == '"') {
        f.quoted = true;
        int open_line = line;
        ++i;
        bool closed = false;
        while (i < n) {
          char c = text[i];
          if (c == '"') {
            if (i + 1 < n && text[i + 1] == '"') {
              f.text += '"';
              i += 2;
              continue;
            }
            ++i;
            closed = true;
            break;
          }
          if (c == '\n') ++line;
          f.text += c;
          ++i;
        }
        if (!closed) {
          error(open_line, f.column, "quoted field never closed (missing '\"')");
          throw LoadError(errors);
        }
        // After the closing quote: the separator, the end of the record, or junk.
        std::size_t junk_start = i;
        while (i < n && text[i] != separator && text[i] != '\n' &&
               !(text[i] == '\r' && i + 1 < n && text[i + 1] == '\n'))
          ++i;
        if (i > junk_start) {
          if (strict)
            error(line, f.column, "text after the closing quote of a quoted field");
          else
            f.text += std::string(text.substr(junk_start, i - junk_start));
        }
      } else {
        bool reported = false;
        while (i < n && text[i] != separator && text[i] != '\n' &&
               !(text[i] == '\r' && i + 1 < n && text[i + 1] == '\n')) {
          if (text[i] == '"' && strict && !reported) {
            error(line, f.column, "quote inside an unquoted field (RFC 4180: quote the field and "
                                  "double the quote)");
            reported = true;  // one report per field is enough; keep reading
          }
          f.text += text[i++];
        }
      }
      rec.fields.push_back(std::move(f));
      if (i >= n) {
        end_of_record = true;
      } else if (text[i] == separator) {
        ++i;
        if (i >= n) {  // a trailing separator at the end of the text: one more empty field
          CsvField last;
          last.line = line;
          last.column = static_cast<int>(rec.fields.size() + 1);
          rec.fields.push_back(last);
          end_of_record = true;
        }
      } else {
        i += text[i] == '\r' ? 2 : 1;
        ++line;
        end_of_record = true;
      }
    }
    records.push_back(std::move(rec));
  }
  if (!errors.empty()) throw LoadError(errors);
  return records;
}

std::string csv_quote(std::string_view field, char separator) {
  bool quote = field.find_first_of(std::string{separator, '"', '\r', '\n'}) != std::string_view::npos ||
               (!field.empty() && (field.front() == ' ' || field.back() == ' ' ||
                                   field.front() == '\t' || field.back() == '\t'));
  if (!quote) return std::string(field);
  std::string out = "\"";
  for (char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

}  // namespace cemv::formats
