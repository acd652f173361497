#include "sheets/workbook_zip.hpp"

#include <stdexcept>

#include <zip.h>

namespace cemv::formats::workbook {

namespace {

std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// 1 January 2000, 00:00 local DOS time: the time of every entry written.
constexpr zip_uint16_t kDosTime = 0;
constexpr zip_uint16_t kDosDate = ((2000 - 1980) << 9) | (1 << 5) | 1;

}  // namespace

ZipReader::ZipReader(std::string_view bytes, std::string file) : file_(std::move(file)) {
  if (bytes.size() > kMaxWorkbookBytes)
    fail("file is " + std::to_string(bytes.size()) + " bytes, larger than the limit of " +
         std::to_string(kMaxWorkbookBytes) + " bytes");
  if (bytes.empty()) fail("not a workbook: the file is empty");
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* src = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  if (src) {
    archive_ = zip_open_from_source(src, ZIP_RDONLY | ZIP_CHECKCONS, &error);
    if (!archive_) zip_source_free(src);
  }
  if (!archive_) {
    std::string reason = zip_error_strerror(&error);
    zip_error_fini(&error);
    fail("not a workbook: the file is not a readable zip archive (" + reason + ")");
  }
  zip_error_fini(&error);
}

ZipReader::~ZipReader() {
  if (archive_) zip_discard(archive_);
}

void ZipReader::fail(const std::string& what) const {
  LoadIssue issue;
  issue.file = file_;
  issue.what = what;
  throw LoadError({issue});
}

bool ZipReader::has(const std::string& name) const { return zip_name_locate(archive_, name.c_str(), 0) >= 0; }

std::optional<std::string> ZipReader::read(const std::string& name) {
  zip_int64_t index = zip_name_locate(archive_, name.c_str(), 0);
  if (index < 0) return std::nullopt;
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat_index(archive_, static_cast<zip_uint64_t>(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
    fail(name + ": the zip directory gives no size for this entry");
  const std::string entry = "zip entry " + name;
  if (st.size > kMaxEntryBytes)
    fail(entry + " would inflate to " + std::to_string(st.size) + " bytes, more than the limit of " +
         mib(kMaxEntryBytes) + " per entry (refused without inflating it)");
  if (total_ + st.size > kMaxTotalBytes)
    fail(entry + ": the entries read would inflate to more than " + mib(kMaxTotalBytes) + " in all");
  zip_file_t* f = zip_fopen_index(archive_, static_cast<zip_uint64_t>(index), 0);
  if (!f) fail(entry + " cannot be read (" + std::string(zip_strerror(archive_)) + ")");
  std::string out;
  out.resize(static_cast<std::size_t>(st.size));
  // One byte more than declared: an entry that inflates past its declared
  // size is refused, not followed.
  std::string extra(1, '\0');
  zip_int64_t got = st.size > 0 ? zip_fread(f, out.data(), st.size) : 0;
  zip_int64_t more = got == static_cast<zip_int64_t>(st.size) ? zip_fread(f, extra.data(), 1) : 0;
  std::string reason = got < 0 || more < 0 ? zip_file_strerror(f) : "";
  zip_fclose(f);
  if (got < 0 || more < 0) fail(entry + " is damaged (" + reason + ")");
  if (got != static_cast<zip_int64_t>(st.size) || more != 0)
    fail(entry + " does not inflate to the " + std::to_string(st.size) + " bytes its directory declares");
  total_ += out.size();
  return out;
}

ZipWriter::ZipWriter() {
  zip_error_t error;
  zip_error_init(&error);
  buffer_ = zip_source_buffer_create(nullptr, 0, 0, &error);
  if (!buffer_) throw std::runtime_error(std::string("zip: ") + zip_error_strerror(&error));
  zip_source_keep(buffer_);  // the bytes are read back after zip_close
  archive_ = zip_open_from_source(buffer_, ZIP_TRUNCATE, &error);
  if (!archive_) {
    std::string reason = zip_error_strerror(&error);
    zip_error_fini(&error);
    zip_source_free(buffer_);
    throw std::runtime_error("zip: " + reason);
  }
  zip_error_fini(&error);
}

ZipWriter::~ZipWriter() {
  if (archive_) zip_discard(archive_);
  if (buffer_) zip_source_free(buffer_);
}

void ZipWriter::add(const std::string& name, std::string data, bool stored) {
  data_.push_back(std::make_unique<std::string>(std::move(data)));
  const std::string& d = *data_.back();
  zip_source_t* src = zip_source_buffer(archive_, d.data(), d.size(), 0);
  if (!src) throw std::runtime_error("zip: " + std::string(zip_strerror(archive_)));
  zip_int64_t index = zip_file_add(archive_, name.c_str(), src, ZIP_FL_ENC_UTF_8);
  if (index < 0) {
    zip_source_free(src);
    throw std::runtime_error("zip: " + std::string(zip_strerror(archive_)));
  }
  auto i = static_cast<zip_uint64_t>(index);
  if (zip_set_file_compression(archive_, i, stored ? ZIP_CM_STORE : ZIP_CM_DEFLATE, 6) != 0 ||
      zip_file_set_dostime(archive_, i, kDosTime, kDosDate, 0) != 0)
    throw std::runtime_error("zip: " + std::string(zip_strerror(archive_)));
}

std::string ZipWriter::finish() {
  if (zip_close(archive_) != 0) throw std::runtime_error("zip: " + std::string(zip_strerror(archive_)));
  archive_ = nullptr;
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_source_stat(buffer_, &st) != 0 || zip_source_open(buffer_) != 0)
    throw std::runtime_error("zip: cannot read the archive back");
  std::string out(static_cast<std::size_t>(st.size), '\0');
  zip_int64_t got = st.size > 0 ? zip_source_read(buffer_, out.data(), st.size) : 0;
  zip_source_close(buffer_);
  if (got != static_cast<zip_int64_t>(st.size)) throw std::runtime_error("zip: cannot read the archive back");
  return out;
}

}  // namespace cemv::formats::workbook
