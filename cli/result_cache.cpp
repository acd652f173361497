#include "cli/result_cache.hpp"

#include <bit>
#include <cstdint>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "checker/check.hpp"
#include "cli/output.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"
#include "properties/print.hpp"

namespace cemv::cli {

namespace {

using nlohmann::json;
using checker::PropertyResult;
using checker::PropertyVerdict;

constexpr const char* kFormat = "cemv-cache/1";

std::optional<PropertyVerdict> verdict_of(const std::string& word) {
  for (auto v : {PropertyVerdict::Proved, PropertyVerdict::Falsified, PropertyVerdict::Reachable,
                 PropertyVerdict::Unreachable, PropertyVerdict::Vacuous, PropertyVerdict::Unknown})
    if (word == checker::to_string(v)) return v;
  return std::nullopt;
}

// Tag values by their bit pattern: every float, NaN and -0 included, comes back exactly.
json trace_json(const checker::ConcreteTrace& t) {
  json inputs = json::array();
  for (const auto& in : t.inputs) {
    json tags = json::array(), commands = json::array();
    for (const auto& v : in.tags) tags.push_back({std::bit_cast<std::uint32_t>(v.value), v.bad_quality});
    for (const auto& c : in.commands)
      commands.push_back({static_cast<int>(c.op), c.cause, c.effect, c.tag, c.group, c.on, c.tag_name,
                          std::bit_cast<std::uint32_t>(c.value)});
    inputs.push_back({{"tags", std::move(tags)}, {"commands", std::move(commands)}});
  }
  return {{"inputs", std::move(inputs)}, {"observables", t.observables}};
}

checker::ConcreteTrace trace_from(const json& j) {
  checker::ConcreteTrace t;
  for (const auto& in : j.at("inputs")) {
    model::CycleInput c;
    for (const auto& v : in.at("tags"))
      c.tags.push_back({std::bit_cast<float>(v.at(0).get<std::uint32_t>()), v.at(1).get<bool>()});
    for (const auto& x : in.at("commands")) {
      model::Command cmd;
      cmd.op = static_cast<model::CommandOp>(x.at(0).get<int>());
      cmd.cause = x.at(1);
      cmd.effect = x.at(2);
      cmd.tag = x.at(3);
      cmd.group = x.at(4);
      cmd.on = x.at(5);
      cmd.tag_name = x.at(6);
      cmd.value = std::bit_cast<float>(x.at(7).get<std::uint32_t>());
      c.commands.push_back(std::move(cmd));
    }
    t.inputs.push_back(std::move(c));
  }
  t.observables = j.at("observables").get<std::vector<std::vector<int>>>();
  return t;
}

// Everything the printers show of a result except its place in the file and
// the files written under --out, which belong to the run.
json result_json(const PropertyResult& p) {
  json support = json::array();
  for (const auto& s : p.support) support.push_back({s.key, s.description});
  return {{"verdict", checker::to_string(p.verdict)},
          {"kind", p.kind},
          {"method", p.method},
          {"depth", p.depth},
          {"reason", p.reason},
          {"invariant", p.invariant},
          {"notes", p.notes},
          {"support", std::move(support)},
          {"support_minimal", p.support_minimal},
          {"trace", p.trace ? trace_json(*p.trace) : json()},
          {"violation_cycle", p.violation_cycle},
          {"timing_table", p.timing_table},
          {"matters", p.matters}};
}

PropertyResult result_from(const json& j) {
  PropertyResult p;
  auto v = verdict_of(j.at("verdict").get<std::string>());
  if (!v) throw std::invalid_argument("verdict");
  p.verdict = *v;
  p.kind = j.at("kind");
  p.method = j.at("method");
  p.depth = j.at("depth");
  p.reason = j.at("reason");
  p.invariant = j.at("invariant");
  p.notes = j.at("notes").get<std::vector<std::string>>();
  for (const auto& s : j.at("support")) p.support.push_back({s.at(0), s.at(1)});
  p.support_minimal = j.at("support_minimal");
  if (!j.at("trace").is_null()) p.trace = trace_from(j.at("trace"));
  p.violation_cycle = j.at("violation_cycle");
  p.timing_table = j.at("timing_table");
  p.matters = j.at("matters").get<std::vector<std::string>>();
  return p;
}

bool needs_trace(PropertyVerdict v) { return v == PropertyVerdict::Falsified || v == PropertyVerdict::Reachable; }

}  // namespace

ResultCache::ResultCache(std::string dir, std::string build, const model::Matrix& m, std::string signature,
                         std::string out_dir, Confirm confirm)
    : dir_(std::move(dir)),
      build_(std::move(build)),
      m_(m),
      signature_(std::move(signature)),
      out_dir_(std::move(out_dir)),
      confirm_(std::move(confirm)) {
  check_writable_directory(dir_);
}

std::string ResultCache::key_text(const properties::PropertyFile& f, const properties::Property& p) const {
  const model::InputTable inputs(m_);
  std::string key = std::string(kFormat) + "\ncemv " + build_ + "\nmatrix " + signature_ + "\nfile " +
                    f.file_name + "\nproperty " + p.name + "\ndescription " + p.description + "\n";
  for (const auto& a : f.assumptions) key += "assume (file) " + a.name + ": " + properties::to_text(a.expr, inputs) + "\n";
  for (const auto& a : p.assumptions) key += "assume " + a.name + ": " + properties::to_text(a.expr, inputs) + "\n";
  return key + properties::statement_text(p, inputs) + "\n";
}

std::string ResultCache::entry_path(const std::string& key_text) const {
  return (std::filesystem::path(dir_) / (formats::sha256_hex(key_text) + ".json")).string();
}

ResultCache::Split ResultCache::split(const std::vector<properties::PropertyFile>& files, int shard_index,
                                      int shard_count) const {
  Split s;
  std::size_t index = 0;
  for (const auto& f : files) {
    properties::PropertyFile rest = f;
    rest.properties.clear();
    for (const auto& p : f.properties) {
      if (!checker::in_shard(index++, shard_index, shard_count)) continue;
      const std::string key = key_text(f, p);
      const std::string path = entry_path(key);
      std::optional<PropertyResult> found;
      std::error_code ec;
      if (std::filesystem::is_regular_file(path, ec)) {
        try {
          const json entry = json::parse(formats::read_text_file(path));
          // The key text itself is stored: a file that is not for this
          // property (however it got there) is never used.
          if (entry.at("format") == kFormat && entry.at("key") == key) {
            PropertyResult r = result_from(entry.at("result"));
            const json& scenario = entry.at("scenario");
            bool usable = r.verdict != PropertyVerdict::Unknown && (!needs_trace(r.verdict) || r.trace);
            if (usable && needs_trace(r.verdict) && !out_dir_.empty()) usable = scenario.is_object();
            if (usable && needs_trace(r.verdict) && confirm_) usable = confirm_(f, p, r);
            if (usable && needs_trace(r.verdict) && !out_dir_.empty()) {
              r.scenario_file = (std::filesystem::path(out_dir_) / scenario.at("name").get<std::string>()).string();
              write_output(r.scenario_file, scenario.at("text").get<std::string>());
            }
            if (usable) found = std::move(r);
          }
        } catch (const formats::LoadError&) {
        } catch (const json::exception&) {
        } catch (const std::invalid_argument&) {
        }
      }
      if (!found) {
        rest.properties.push_back(p);
        continue;
      }
      found->name = p.name;
      found->description = p.description;
      found->file = f.file_name;
      found->line = p.loc.line;
      found->column = p.loc.column;
      found->cached = true;
      s.cached[{f.file_name, p.name}] = std::move(*found);
    }
    s.to_check.push_back(std::move(rest));
  }
  return s;
}

void ResultCache::store(const std::vector<properties::PropertyFile>& files, const checker::CheckResult& r) const {
  for (const auto& result : r.properties) {
    if (result.cached || result.verdict == PropertyVerdict::Unknown) continue;
    if (needs_trace(result.verdict) && !result.trace) continue;
    for (const auto& f : files) {
      if (f.file_name != result.file) continue;
      for (const auto& p : f.properties) {
        if (p.name != result.name) continue;
        const std::string key = key_text(f, p);
        json scenario;
        if (!result.scenario_file.empty())
          scenario = {{"name", std::filesystem::path(result.scenario_file).filename().string()},
                      {"text", formats::read_text_file(result.scenario_file)}};
        json entry = {{"format", kFormat}, {"key", key}, {"result", result_json(result)}, {"scenario", scenario}};
        write_output(entry_path(key), entry.dump(1, ' ', false, json::error_handler_t::replace) + "\n");
      }
    }
  }
}

checker::CheckResult check_with_cache(const ResultCache& cache, const model::Matrix& m,
                                      const std::vector<properties::PropertyFile>& files,
                                      checker::CheckOptions options) {
  ResultCache::Split split = cache.split(files, options.shard_index, options.shard_count);
  if (options.on_result)
    for (const auto& [key, r] : split.cached) options.on_result(r);
  const int shard_index = options.shard_index, shard_count = options.shard_count;
  options.shard_index = options.shard_count = 1;  // to_check holds this shard's properties only
  checker::CheckResult checked = checker::check_properties(m, split.to_check, options);

  std::map<std::pair<std::string, std::string>, PropertyResult*> decided;
  for (auto& p : checked.properties) decided[{p.file, p.name}] = &p;
  checker::CheckResult out = checked;
  out.properties.clear();
  std::size_t index = 0;
  for (const auto& f : files)
    for (const auto& p : f.properties) {
      if (!checker::in_shard(index++, shard_index, shard_count)) continue;
      const std::pair<std::string, std::string> key{f.file_name, p.name};
      if (auto c = split.cached.find(key); c != split.cached.end())
        out.properties.push_back(c->second);
      else if (auto d = decided.find(key); d != decided.end())
        out.properties.push_back(std::move(*d->second));
    }
  std::erase_if(out.unsupported, [&](const checker::SupportElement& e) {
    for (const auto& [key, r] : split.cached)
      for (const auto& s : r.support)
        if (s.key == e.key) return true;
    return false;
  });
  return out;
}

}  // namespace cemv::cli
