// The fields of cemv-matrix/1 that the spreadsheet layouts carry as property
// rows, key and value (docs/csv.md, docs/workbook.md): tag descriptions,
// which tags may not be simulated, and the provenance records. One set of
// keys for the record layout and the workbook, so both stay lossless.
//   tag.NAME.description               the tag's description
//   cause.ID.tag.N.simulation_allowed  false (only written when false)
//   effect.ID.tag.N.simulation_allowed false
//   provenance.import.K                one import record, as canonical JSON
//   provenance.parameters.K            one parameters record, as canonical JSON
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::formats {

struct ExtraProperty {
  std::string key;
  std::string value;
};

// The rows for `m`, in a fixed order (tags by name, elements by id, records in order).
std::vector<ExtraProperty> extra_properties(const model::Matrix& m);

// Whether `key` is one of these rows' keys (its shape, not whether it applies).
bool is_extra_property(std::string_view key);

// Applies rows to a matrix whose elements are read; returns, per row that
// cannot apply, its index and why (no such element or tag position, a value
// that is not `false`, a record that is not the format's JSON).
std::vector<std::pair<std::size_t, std::string>> apply_extra_properties(model::Matrix& m,
                                                                        const std::vector<ExtraProperty>& rows);

}  // namespace cemv::formats
