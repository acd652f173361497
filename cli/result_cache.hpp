// `cemv check --cache DIR` (docs/checker.md, "Result cache"): the verdicts of
// earlier runs, one file per property under DIR, each found by a key of the
// cemv build, the matrix signature and the property's text (as the parser
// resolved it, with the file's assumptions), so that a CI pipeline that keeps
// DIR between runs decides again only what changed. Unknown verdicts are
// never stored. A stored counterexample or witness is replayed on the
// reference runtime before it is reported again (when a `confirm` is given).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "checker/check.hpp"
#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::cli {

class ResultCache {
 public:
  using Confirm = std::function<bool(const properties::PropertyFile&, const properties::Property&,
                                     const checker::PropertyResult&)>;
  // `dir` is created when missing. `build` names this binary exactly (version
  // and commit), `signature` the matrix; `out_dir` is the run's --out ("" for
  // none): a cached counterexample's scenario file is written there again.
  ResultCache(std::string dir, std::string build, const model::Matrix& m, std::string signature,
              std::string out_dir, Confirm confirm);

  // Splits the properties that shard i of n checks (checker::in_shard over
  // the concatenated list): those with a usable stored result come back
  // restored (their place in the file as it is now) in `cached`; `to_check`
  // holds the same files with only the other properties.
  struct Split {
    std::vector<properties::PropertyFile> to_check;
    std::map<std::pair<std::string, std::string>, checker::PropertyResult> cached;  // (file, name)
  };
  Split split(const std::vector<properties::PropertyFile>& files, int shard_index, int shard_count) const;

  // Stores every decided verdict of `r` that was not taken from the cache.
  void store(const std::vector<properties::PropertyFile>& files, const checker::CheckResult& r) const;

  const std::string& dir() const { return dir_; }

 private:
  std::string key_text(const properties::PropertyFile& f, const properties::Property& p) const;
  std::string entry_path(const std::string& key_text) const;

  std::string dir_;
  std::string build_;
  const model::Matrix& m_;
  std::string signature_;
  std::string out_dir_;
  Confirm confirm_;
};

// checker::check_properties through the cache: the stored results of shard
// i of n are reported (on_result is called for each first), only the rest is
// decided, and the result lists every property of the shard in the
// checker's order (store() then keeps what it decided). The elements a
// cached proof needs are taken off `unsupported`.
checker::CheckResult check_with_cache(const ResultCache& cache, const model::Matrix& m,
                                      const std::vector<properties::PropertyFile>& files,
                                      checker::CheckOptions options);

}  // namespace cemv::cli
