// What `cemv evidence` reads besides the matrix and the properties: the
// results of `cemv testgen` (cemv-coverage/1, docs/testgen.md) and of
// `cemv testgen --mutation-report` (cemv-mutation-report/1, docs/mutation.md)
// and of `cemv defeats` (cemv-defeats/1, docs/defeats.md).
// A file made for another version of the matrix (another signature) is
// refused: the report ties every figure to the one matrix it names.
#pragma once

#include <map>
#include <string>

#include "model/matrix.hpp"
#include "reports/evidence.hpp"
#include "response/search.hpp"

namespace cemv::cli {

// Throw formats::LoadError (FILE: error: PATH: what) for unreadable files,
// wrong formats and other signatures.
reports::CoverageFigures read_coverage(const std::string& file, const model::Matrix& m);
reports::MutationFigures read_mutation(const std::string& file, const model::Matrix& m);
// The minimal defeat sets of `cemv defeats --format json` (cemv-defeats/1, docs/defeats.md).
reports::DefeatFigures read_defeats(const std::string& file, const model::Matrix& m);

// The logic figures of `cemv response --format json` (cemv-response/1,
// docs/response-time.md) by path key, for `cemv defeats --response`: the
// exact and unbounded ones (an unknown figure is left out, to be decided
// again). `keys` names the matrix's paths: "1,2>3" (trigger causes, effect)
// to the path's key; a path not among them is refused.
std::map<std::string, response::Figure> read_response_figures(const std::string& file, const model::Matrix& m,
                                                              const std::map<std::string, std::string>& keys);

}  // namespace cemv::cli
