// The zip container of ODS and XLSX (internal to formats/), on libzip: reading
// entries of an archive held in memory under the size limits of
// workbook_sheet.hpp, and writing an archive into memory deterministically.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sheets/workbook_sheet.hpp"

struct zip;
struct zip_source;

namespace cemv::formats::workbook {

class ZipReader {
 public:
  // Opens the archive (refuses one larger than kMaxWorkbookBytes or not a zip:
  // LoadError naming `file`). `bytes` must outlive the reader.
  ZipReader(std::string_view bytes, std::string file);
  ~ZipReader();
  ZipReader(const ZipReader&) = delete;
  ZipReader& operator=(const ZipReader&) = delete;

  bool has(const std::string& name) const;
  // The inflated entry, nullopt when the archive has none of that name. The
  // size the zip directory declares is checked before inflating (a zip bomb
  // is refused without inflating it), and the inflated bytes are counted too,
  // in case the directory lies: more than kMaxEntryBytes in one entry or
  // kMaxTotalBytes in all is refused.
  std::optional<std::string> read(const std::string& name);
  const std::string& file() const { return file_; }
  // Throws a LoadError naming the file.
  [[noreturn]] void fail(const std::string& what) const;

 private:
  ::zip* archive_ = nullptr;
  std::string file_;
  std::size_t total_ = 0;
};

class ZipWriter {
 public:
  ZipWriter();
  ~ZipWriter();
  ZipWriter(const ZipWriter&) = delete;
  ZipWriter& operator=(const ZipWriter&) = delete;
  // Entries in the order added; `stored` leaves one uncompressed (the ODS
  // `mimetype`, which must come first and uncompressed). Every entry carries
  // the same fixed time, so the same workbook gives the same bytes.
  void add(const std::string& name, std::string data, bool stored = false);
  std::string finish();  // the archive's bytes

 private:
  ::zip_source* buffer_ = nullptr;
  ::zip* archive_ = nullptr;
  std::vector<std::unique_ptr<std::string>> data_;  // kept alive until finish()
};

}  // namespace cemv::formats::workbook
