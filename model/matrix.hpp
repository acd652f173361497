// The cause & effect matrix as data: one struct per element of the format
// `cemv-matrix/1` (docs/format.md). No semantics live here: the runtime and the
// encoder each give these fields their meaning from docs/semantics.md.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cemv::model {

inline constexpr const char* kMatrixFormat = "cemv-matrix/1";

// Limits of 3.4 ("Definition of terms").
inline constexpr int kMaxCauses = 128;
inline constexpr int kMaxEffects = 128;
inline constexpr int kMaxIntersections = 1024;
inline constexpr int kMaxCauseTags = 3;
inline constexpr int kMaxEffectTags = 4;
inline constexpr int kMaxSifGroups = 64;
inline constexpr int kMaxSifPerElement = 4;
inline constexpr int kMaxFirstOutGroup = 15;
inline constexpr int kMinXooN = 2;
inline constexpr int kMaxXooN = 15;
inline constexpr std::size_t kMaxTagNameLength = 24;   // 6.1.4
inline constexpr std::size_t kMaxElementNameLength = 32;
inline constexpr std::size_t kMaxDescriptionLength = 80;

enum class InputKind { Discrete, Analog };                      // 6.3.4
enum class CauseFunction { Normal, And, Or, TwoOoThree, Comment };  // 3.4, 6.3.1
enum class LimitType { High, Low };                             // 6.3.5
enum class BadQuality { Ignore, Trip, Degrade };                // 6.1.6, 13.1.5
enum class TimeMode { None, OnDelay, OffDelay, Timed };         // 6.3.6, 13.1.1
enum class EffectFunction { Normal, Comment };                  // 6.4.4
// X: "not yet specified"; Note: "*" (for note only, not processed). 6.5.2
enum class IntersectionType { N, S, V, R, X, Note };

struct CauseTag {
  std::string name;
  bool ett = false;                  // energize-to-trip; default de-energize-to-trip
  bool soft_bypass_allowed = true;
  // Whether the operator may simulate the tag (O.8; the manual's F-channel
  // driver interconnection for "Simulating a tag", 10.7.3.4).
  bool simulation_allowed = true;
};

struct AnalogParams {
  LimitType limit_type = LimitType::High;
  // IEEE single precision, as the F-CPU's REAL (6.3.1).
  float limit = 0.0f;
  float hysteresis = 0.0f;
  std::optional<float> prewarning;
  float delta = 0.0f;                // 0 = discrepancy alarm off
  std::string unit;
};

struct TimeFunction {
  TimeMode mode = TimeMode::None;
  std::uint32_t ms = 0;
};

struct CauseSoftBypass {
  bool allowed = true;
  std::uint32_t max_s = 0;           // 0 = untimed
  std::uint32_t prealarm_s = 0;
};

struct Cause {
  int id = 0;
  std::string name;
  std::string description;
  int sil = 0;                       // 0 = not stated
  InputKind input = InputKind::Discrete;
  CauseFunction function = CauseFunction::Normal;
  std::vector<CauseTag> tags;
  std::optional<AnalogParams> analog;
  BadQuality bad_quality = BadQuality::Trip;
  TimeFunction time;
  bool auto_ack = true;
  CauseSoftBypass soft_bypass;
  std::optional<std::string> bypass_tag;
  std::optional<std::string> inhibit_tag;
  int first_out_group = 0;           // 0 = none, 1-15
  bool mutually_locked_maintenance = false;
  std::vector<int> sif;
  std::string note;                  // free text (e.g. footnotes of an imported grid)
  // Declared response time of the field device (transmitter damping, switch
  // delay), ms; only `cemv response` reads it (docs/response-time.md).
  std::uint32_t sensor_ms = 0;
};

struct EffectTag {
  std::string name;
  bool ett = false;                  // DTT: output 0 while the effect is active
  bool simulation_allowed = true;    // as CauseTag::simulation_allowed (O.8)
};

struct Override {
  std::uint32_t max_s = 0;
  std::uint32_t prealarm_s = 0;
};

struct ProcessData {
  std::optional<std::string> tag;    // BPCS process value
  bool pass_through = false;
  std::optional<std::string> mask_tag;
};

struct Effect {
  int id = 0;
  std::string name;
  std::string description;
  int sil = 0;
  EffectFunction function = EffectFunction::Normal;
  std::vector<EffectTag> tags;
  std::uint32_t output_delay_ms = 0;
  bool soft_bypass_allowed = false;
  std::optional<std::string> bypass_tag;
  std::optional<std::string> reset_tag;
  std::optional<Override> override_time;   // JSON key "override"
  std::optional<ProcessData> process_data;
  bool mutually_locked_maintenance = false;
  std::vector<int> sif;
  std::string note;
  // Declared response time of the final element (a valve's stroke time), ms;
  // only `cemv response` reads it (docs/response-time.md).
  std::uint32_t actuator_ms = 0;
};

struct Intersection {
  int cause = 0;
  int effect = 0;
  IntersectionType type = IntersectionType::N;
  std::optional<int> xoon;           // X of an XooN majority assignment
  std::string note;                  // e.g. footnote references "(1)"
};

struct SecureWrite {
  std::string enable_tag;
};

struct GroupDeactivation {
  std::string enable_tag;
  std::string set_tag;
};

// Where a matrix came from (docs/format.md "Provenance"): written by the
// importers and by `cemv apply-params`, covered by the signature, read by the
// evidence report; no scan-cycle meaning (M.5).
struct ImportRecord {
  std::string file;                   // the source's base name
  std::string sha256;                 // of the source's bytes
  std::string reader;                 // "import-csv grid", "import-workbook grid", ...
  std::string encoding;               // "UTF-8", "Windows-1252"
  std::string summary;                // how the source was read
  std::vector<std::string> warnings;  // the import's warnings, as printed
  std::vector<std::string> defaults;  // what the source does not state and the import took from the format
};

// One value a parameters file set (cemv-params/1, docs/params.md).
struct ParameterValue {
  std::string element;   // "matrix", "cause[3] NAME", "effect[1] NAME", "tag NAME", "intersection cause[1]/effect[2]"
  std::string field;     // the field's path in the element: "override.max_s", "tags[1].simulation_allowed"
  std::string value;     // JSON text of the value set
  std::string previous;  // JSON text of the value it replaced
  std::string origin;    // where the value comes from, as the parameters file says
};

// A footnote of the source sheet and what the model makes of it.
struct FootnoteRecord {
  std::string mark;          // "(1)"
  std::string text;          // the legend's text
  std::string modelled;      // how the parameters express it ("" = not)
  std::string not_modelled;  // why the model cannot express it ("" = it can)
};

struct ParameterRecord {
  std::string file;                      // the parameters file's base name
  std::string sha256;                    // of its bytes
  std::string origin;                    // what the file as a whole rests on
  std::vector<ParameterValue> values;    // in the order applied
  std::vector<FootnoteRecord> footnotes;
  std::vector<std::string> limitations;  // what the source states and the model does not
};

struct Provenance {
  std::vector<ImportRecord> imports;
  std::vector<ParameterRecord> parameters;
  bool empty() const { return imports.empty() && parameters.empty(); }
};

struct Matrix {
  std::string name;
  std::string title;
  std::uint32_t cycle_ms = 100;
  std::map<int, std::string> sif_groups;
  // Process safety time per SIF group, ms (IEC 61508-4; HIMatrix Safety
  // Manual 3.2.1), for the groups that declare one (JSON: the object form of a
  // sif_groups entry). Groups without an entry declare none.
  std::map<int, std::uint32_t> process_safety_time_ms;
  // The controller's watchdog time, ms (HIMatrix 3.2.3); absent = not declared.
  std::optional<std::uint32_t> watchdog_ms;
  std::optional<SecureWrite> secure_write;
  std::optional<GroupDeactivation> group_deactivation;
  std::vector<Cause> causes;          // kept sorted by id
  std::vector<Effect> effects;        // kept sorted by id
  std::vector<Intersection> intersections;  // sorted by (cause, effect)
  // Descriptions of tags (documentation, M.5), by tag name as written; names
  // compare case-insensitively (6.1.4), so no two keys differ only in case.
  std::map<std::string, std::string> tag_descriptions;
  Provenance provenance;

  // Restores the order the fields above promise (find_* binary-search it).
  // Stable, so elements with a repeated id (validate() reports them) keep
  // their file order and every platform sorts them alike.
  void sort_by_id();

  const Cause* find_cause(int id) const;
  const Effect* find_effect(int id) const;
  const Intersection* find_intersection(int cause, int effect) const;
  // The intersections of one effect, in cause order.
  std::vector<const Intersection*> intersections_of_effect(int effect) const;
  std::vector<const Intersection*> intersections_of_cause(int cause) const;
};

// Names of the enumerations exactly as they appear in the JSON format.
const char* to_string(InputKind);
const char* to_string(CauseFunction);
const char* to_string(LimitType);
const char* to_string(BadQuality);
const char* to_string(TimeMode);
const char* to_string(EffectFunction);
const char* to_string(IntersectionType);

// Number of tags a function type takes: {min, max} (3.4, 6.3.1).
struct TagCount { int min; int max; };
TagCount tag_count_of(CauseFunction);

// Whether an intersection type takes part in the scan cycle (6.5.2: X cannot be
// transferred, "*" is for note only).
bool is_processed(IntersectionType);

}  // namespace cemv::model
