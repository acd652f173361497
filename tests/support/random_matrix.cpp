#include "tests/support/random_matrix.hpp"

#include <algorithm>
#include <cctype>
#include <deque>
#include <optional>
#include <set>
#include <string>

#include "model/vocabulary.hpp"

namespace cemv::testsupport {

// ---- PRNG -------------------------------------------------------------------

std::uint64_t Rng::next() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

int Rng::uniform(int lo, int hi) {
  auto span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo + 1);
  // Rejection sampling keeps the draw exactly uniform (and platform independent).
  std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
  std::uint64_t x;
  do x = next();
  while (x >= limit);
  return lo + static_cast<int>(x % span);
}

bool Rng::chance(double p) {
  // 53 random bits as an exact double in [0, 1).
  return static_cast<double>(next() >> 11) * 0x1.0p-53 < p;
}

namespace {

using namespace cemv::model;

// ---- Helpers ----------------------------------------------------------------

// Quarter steps are exact in single precision, so every threshold and value the
// generator writes round-trips through the canonical JSON unchanged.
float quarters(int n) { return static_cast<float>(n) / 4.0f; }

constexpr std::uint32_t kCycles[] = {10, 20, 50, 100, 200, 250, 500, 1000};

const std::vector<std::string> kAnalogPrefixes = {"LT", "PT", "TT", "FT", "AT"};
const std::vector<std::string> kDiscretePrefixes = {"PSHH", "LSLL", "ZSC", "HS", "FSL", "BSL"};
const std::vector<std::string> kOutputPrefixes = {"XV", "SDV", "MTR", "BDV", "HV"};
const std::vector<std::string> kUnits = {"%", "bar", "degC", "m3/h", "ppm", ""};

std::string letter(int k) { return std::string(1, static_cast<char>('A' + k)); }

bool is_ref(const std::string& name) { return parse_internal_ref(name).has_value(); }

bool has_tag(const Cause& c, const std::string& name) {
  for (const auto& t : c.tags)
    if (tag_key(t.name) == tag_key(name)) return true;
  return false;
}

// Seconds of a soft bypass or override that a 300-cycle run can see expire.
int max_seconds(std::uint32_t cycle_ms) {
  return std::clamp(static_cast<int>(100 * cycle_ms / 1000), 1, 10);
}

std::uint32_t short_duration(Rng& rng, std::uint32_t cycle_ms) {
  int cycles = rng.chance(0.9) ? rng.uniform(1, 10) : rng.uniform(11, 50);
  return static_cast<std::uint32_t>(cycles) * cycle_ms;
}

std::vector<int> random_sif(Rng& rng, const std::map<int, std::string>& groups) {
  std::vector<int> all;
  for (const auto& [k, v] : groups) all.push_back(k);
  std::vector<int> out;
  int n = all.empty() ? 0 : rng.uniform(0, std::min<int>(kMaxSifPerElement, static_cast<int>(all.size())));
  while (static_cast<int>(out.size()) < n) {
    int g = rng.pick(all);
    if (std::find(out.begin(), out.end(), g) == out.end()) out.push_back(g);
  }
  std::sort(out.begin(), out.end());
  return out;
}

CauseFunction random_function(Rng& rng) {
  int r = rng.uniform(0, 99);
  if (r < 40) return CauseFunction::Normal;
  if (r < 55) return CauseFunction::And;
  if (r < 75) return CauseFunction::Or;
  return CauseFunction::TwoOoThree;
}

IntersectionType random_type(Rng& rng) {
  int r = rng.uniform(0, 99);
  if (r < 40) return IntersectionType::N;
  if (r < 60) return IntersectionType::S;
  if (r < 80) return IntersectionType::V;
  return IntersectionType::R;
}

AnalogParams random_analog(Rng& rng, int tag_count) {
  AnalogParams a;
  a.limit_type = rng.chance(0.5) ? LimitType::High : LimitType::Low;
  a.limit = quarters(rng.uniform(-200, 800));
  a.hysteresis = rng.chance(0.35) ? 0.0f : quarters(rng.uniform(1, 20));
  if (rng.chance(0.45)) {
    // Prewarning on the safe side of the limit (6.3.5): below a high limit,
    // above a low one.
    float d = quarters(rng.uniform(1, 40));
    a.prewarning = a.limit_type == LimitType::High ? a.limit - d : a.limit + d;
  }
  if (tag_count >= 2 && rng.chance(0.55)) {
    a.delta = quarters(rng.uniform(2, 40));
    // The delta alarm clears below delta - hysteresis: keep that positive.
    if (a.hysteresis >= a.delta) a.hysteresis = a.delta / 2.0f;
  }
  a.unit = rng.pick(kUnits);
  return a;
}

void make_cause(Rng& rng, const MatrixOptions& opt, Matrix& m, Cause& c, bool comment) {
  c.name = "C" + std::to_string(c.id) + "_" + (comment ? "NOTE" : "TRIP");
  c.sil = rng.uniform(0, 3);
  c.sif = random_sif(rng, m.sif_groups);
  if (comment) {
    // A comment line (3.4): never processed, keeps its (unique) tags for display.
    c.function = CauseFunction::Comment;
    c.description = "Comment line " + std::to_string(c.id);
    int n = rng.uniform(0, 2);
    for (int k = 0; k < n; ++k) c.tags.push_back({"CMT_" + std::to_string(c.id) + letter(k), false, true});
    return;
  }
  c.input = rng.chance(opt.p_analog) ? InputKind::Analog : InputKind::Discrete;
  c.function = random_function(rng);
  auto count = tag_count_of(c.function);
  int ntags = rng.uniform(count.min, count.max);
  bool analog = c.input == InputKind::Analog;
  const auto& prefixes = analog ? kAnalogPrefixes : kDiscretePrefixes;
  std::string base = rng.pick(prefixes) + "_" + std::to_string(100 + c.id);
  for (int k = 0; k < ntags; ++k) {
    CauseTag t;
    t.name = base + letter(k);
    // Real matrices read one transmitter or switch from several causes (for
    // example a high and a high-high limit on one level transmitter).
    if (rng.chance(opt.p_shared_tag)) {
      std::vector<std::string> candidates;
      for (const auto& other : m.causes)
        if (other.function != CauseFunction::Comment && other.input == c.input)
          for (const auto& ot : other.tags)
            if (!is_ref(ot.name) && !has_tag(c, ot.name)) candidates.push_back(ot.name);
      if (!candidates.empty()) {
        t.name = rng.pick(candidates);
        if (rng.chance(0.3)) {  // tag names match case-insensitively (6.1.4)
          for (auto& ch : t.name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        }
      }
    }
    if (has_tag(c, t.name)) t.name = base + letter(k);
    t.ett = !analog && rng.chance(opt.p_ett);
    t.soft_bypass_allowed = rng.chance(0.85);
    c.tags.push_back(t);
  }
  if (analog) c.analog = random_analog(rng, ntags);
  c.description = std::string(analog ? "Analog " : "Discrete ") + to_string(c.function) + " trip of " + base;

  int bq = rng.uniform(0, 2);
  c.bad_quality = bq == 0 ? BadQuality::Ignore : bq == 1 ? BadQuality::Trip : BadQuality::Degrade;
  if (rng.chance(opt.p_time)) {
    int t = rng.uniform(0, 2);
    c.time.mode = t == 0 ? TimeMode::OnDelay : t == 1 ? TimeMode::OffDelay : TimeMode::Timed;
    c.time.ms = short_duration(rng, m.cycle_ms);
  }
  // Manual acknowledgement exists only without time function or with ON delay (6.3.6).
  if ((c.time.mode == TimeMode::None || c.time.mode == TimeMode::OnDelay) && rng.chance(opt.p_manual_ack))
    c.auto_ack = false;
  c.soft_bypass.allowed = rng.chance(0.8);
  if (c.soft_bypass.allowed && rng.chance(0.5)) {
    c.soft_bypass.max_s = static_cast<std::uint32_t>(rng.uniform(1, max_seconds(m.cycle_ms)));
    if (c.soft_bypass.max_s > 1 && rng.chance(0.6))
      c.soft_bypass.prealarm_s = static_cast<std::uint32_t>(rng.uniform(1, static_cast<int>(c.soft_bypass.max_s) - 1));
  }
  if (rng.chance(opt.p_bypass_tag)) {
    c.bypass_tag = "HS_" + std::to_string(c.id) + "_BYP";
    // One bypass switch for several causes (e.g. a start-up bypass).
    for (auto it = m.causes.rbegin(); it != m.causes.rend(); ++it)
      if (it->bypass_tag && rng.chance(0.2)) {
        c.bypass_tag = it->bypass_tag;
        break;
      }
  }
  if (rng.chance(opt.p_inhibit_tag)) c.inhibit_tag = "IS_" + std::to_string(c.id) + "_INH";
  if (rng.chance(opt.p_first_out)) c.first_out_group = rng.chance(0.9) ? rng.uniform(1, 3) : kMaxFirstOutGroup;
  c.mutually_locked_maintenance = rng.chance(0.25);
  if (rng.chance(0.05)) c.note = "see P&ID sheet " + std::to_string(rng.uniform(1, 40));
}

void make_effect(Rng& rng, const MatrixOptions& opt, Matrix& m, Effect& e, bool comment) {
  e.name = "E" + std::to_string(e.id) + "_" + (comment ? "NOTE" : "ACT");
  e.sil = rng.uniform(0, 3);
  e.sif = random_sif(rng, m.sif_groups);
  std::string base = rng.pick(kOutputPrefixes) + "_" + std::to_string(500 + e.id);
  if (comment) {
    e.function = EffectFunction::Comment;
    e.description = "Comment column " + std::to_string(e.id);
    e.tags.push_back({"CMT_E" + std::to_string(e.id), false});
    return;
  }
  e.description = "Shut down " + base;
  int r = rng.uniform(0, 9);
  int ntags = r < 5 ? 1 : r < 7 ? 2 : r < 9 ? 3 : 4;
  for (int k = 0; k < ntags; ++k) e.tags.push_back({base + letter(k), rng.chance(opt.p_ett)});
  if (rng.chance(opt.p_output_delay)) e.output_delay_ms = short_duration(rng, m.cycle_ms);
  e.soft_bypass_allowed = rng.chance(0.4);
  if (rng.chance(opt.p_bypass_tag)) e.bypass_tag = "HS_E" + std::to_string(e.id) + "_BYP";
  if (rng.chance(opt.p_reset_tag)) {
    e.reset_tag = "HS_" + std::to_string(e.id) + "_RST";
    // A common reset push-button for several effects.
    for (auto it = m.effects.rbegin(); it != m.effects.rend(); ++it)
      if (it->reset_tag && rng.chance(0.2)) {
        e.reset_tag = it->reset_tag;
        break;
      }
  }
  if (rng.chance(opt.p_process_data)) {
    ProcessData pd;
    pd.tag = base + "_BPCS";
    int kind = rng.uniform(0, 2);  // pass-through, mask, both (13.2.5)
    pd.pass_through = kind != 1;
    if (kind != 0) pd.mask_tag = base + "_MASK";
    e.process_data = pd;
  }
  e.mutually_locked_maintenance = rng.chance(0.25);
  if (rng.chance(0.05)) e.note = "interlock also in BPCS";
}

// Whether `to` depends on `from` through intersections and internal references:
// tells whether a reference closes a cycle (feature "ref.cycle").
bool reaches(const Matrix& m, Node from, Node to) {
  // Edges: cause -> effect (processed intersections); referenced element ->
  // reading cause (internal references).
  std::set<Node> seen{from};
  std::deque<Node> todo{from};
  while (!todo.empty()) {
    Node n = todo.front();
    todo.pop_front();
    if (n == to) return true;
    std::vector<Node> next;
    if (n.kind == Node::Kind::Cause) {
      for (const auto& x : m.intersections)
        if (x.cause == n.id && is_processed(x.type)) next.push_back({Node::Kind::Effect, x.effect});
    }
    for (const auto& c : m.causes) {
      if (c.function == CauseFunction::Comment) continue;
      for (const auto& t : c.tags) {
        auto r = parse_internal_ref(t.name);
        if (!r) continue;
        Node src{r->kind == InternalRef::Kind::Cause ? Node::Kind::Cause : Node::Kind::Effect, r->id};
        if (src == n) next.push_back({Node::Kind::Cause, c.id});
      }
    }
    for (const auto& x : next)
      if (seen.insert(x).second) todo.push_back(x);
  }
  return false;
}

void add_intersections(Rng& rng, const MatrixOptions& opt, Matrix& m) {
  std::vector<int> causes, effects;
  for (const auto& c : m.causes)
    if (c.function != CauseFunction::Comment) causes.push_back(c.id);
  for (const auto& e : m.effects)
    if (e.function != EffectFunction::Comment) effects.push_back(e.id);
  if (causes.empty() || effects.empty()) return;  // options asked for an empty side
  int grid = static_cast<int>(causes.size() * effects.size());
  int target = opt.intersections >= 0 ? opt.intersections : (grid * 4 + 5) / 10;
  target = std::clamp(target, static_cast<int>(std::max(causes.size(), effects.size())),
                      std::min(grid, kMaxIntersections));
  std::set<std::pair<int, int>> pairs, guaranteed;
  // Every processed cause drives something and every processed effect is driven
  // (otherwise 11.5 warns about unused elements).
  for (int c : causes) {
    auto p = std::pair{c, rng.pick(effects)};
    pairs.insert(p);
    guaranteed.insert(p);
  }
  for (int e : effects) {
    bool fed = std::any_of(pairs.begin(), pairs.end(), [&](const auto& p) { return p.second == e; });
    if (!fed) {
      auto p = std::pair{rng.pick(causes), e};
      pairs.insert(p);
      guaranteed.insert(p);
    }
  }
  while (static_cast<int>(pairs.size()) < target) pairs.insert({rng.pick(causes), rng.pick(effects)});
  // (A requested count below the guaranteed pairs is exceeded, never the 3.4 limit:
  // at most 128 + 128 of them.)
  for (const auto& [c, e] : pairs) {
    Intersection x;
    x.cause = c;
    x.effect = e;
    x.type = !guaranteed.count({c, e}) && rng.chance(opt.p_note_intersection) ? IntersectionType::Note
                                                                               : random_type(rng);
    if (rng.chance(0.03)) x.note = "(" + std::to_string(rng.uniform(1, 9)) + ")";
    m.intersections.push_back(x);
  }
  // XooN majority assignments (6.5.2): at most one per effect, all of one type.
  for (auto& e : m.effects) {
    std::vector<Intersection*> own;
    for (auto& x : m.intersections)
      if (x.effect == e.id && is_processed(x.type)) own.push_back(&x);
    if (own.size() < 2 || !rng.chance(opt.p_xoon)) continue;
    int n = rng.uniform(2, std::min<int>(static_cast<int>(own.size()), kMaxXooN));
    // A random subset of n of them, in cause order.
    for (int i = static_cast<int>(own.size()) - 1; i > 0; --i) std::swap(own[i], own[rng.uniform(0, i)]);
    own.resize(n);
    IntersectionType type = random_type(rng);
    int x = rng.uniform(kMinXooN, n);
    for (auto* p : own) {
      p->type = type;
      p->xoon = x;
    }
  }
  // V and R need the maximum override time (6.5.2).
  for (auto& e : m.effects) {
    bool overridable = false;
    for (const auto& x : m.intersections)
      if (x.effect == e.id && (x.type == IntersectionType::V || x.type == IntersectionType::R)) overridable = true;
    if (!overridable) continue;
    Override o;
    o.max_s = static_cast<std::uint32_t>(rng.uniform(1, max_seconds(m.cycle_ms)));
    if (o.max_s > 1 && rng.chance(0.6)) o.prealarm_s = static_cast<std::uint32_t>(rng.uniform(1, static_cast<int>(o.max_s) - 1));
    e.override_time = o;
  }
}

// Internal references (6.1.3) as input tags of discrete causes; some are chosen
// to close a cycle (the graph then reads the previous cycle's value, 4).
void add_internal_refs(Rng& rng, const MatrixOptions& opt, Matrix& m) {
  std::vector<const Cause*> causes;
  std::vector<const Effect*> effects;
  for (const auto& c : m.causes)
    if (c.function != CauseFunction::Comment) causes.push_back(&c);
  for (const auto& e : m.effects)
    if (e.function != EffectFunction::Comment) effects.push_back(&e);
  for (auto& c : m.causes) {
    if (c.function == CauseFunction::Comment || c.input != InputKind::Discrete) continue;
    for (auto& t : c.tags) {
      if (!rng.chance(opt.p_internal_ref)) continue;
      std::vector<int> fed;  // effects this cause drives: referencing one closes a cycle
      for (const auto& x : m.intersections)
        if (x.cause == c.id && is_processed(x.type)) fed.push_back(x.effect);
      std::string name;
      int kind = rng.uniform(0, 2);
      if (kind == 0 && causes.size() > 1) {
        const Cause* other = rng.pick(causes);
        if (other->id != c.id) name = "Cause[" + std::to_string(other->id) + "]";
      } else {
        if (effects.empty()) continue;
        const Effect* e = rng.pick(effects);
        if (!fed.empty() && rng.chance(opt.p_cycle_ref)) e = m.find_effect(rng.pick(fed));
        name = "Effect[" + std::to_string(e->id) + "]";
        if (kind == 2) name += "[" + std::to_string(rng.uniform(1, static_cast<int>(e->tags.size()))) + "]";
      }
      if (name.empty() || has_tag(c, name)) continue;
      t.name = name;
      t.ett = rng.chance(0.5);
    }
  }
}

// Internal references as control tags (6.1.3: any input tag may read the state
// of a cause, an effect or an effect tag): a cause bypassed or inhibited by
// another cause, an effect reset by a cause. Never the element itself.
void add_control_refs(Rng& rng, const MatrixOptions& opt, Matrix& m) {
  std::vector<int> causes, effects;
  for (const auto& c : m.causes)
    if (c.function != CauseFunction::Comment) causes.push_back(c.id);
  for (const auto& e : m.effects)
    if (e.function != EffectFunction::Comment) effects.push_back(e.id);
  auto reference = [&](bool self_is_cause, int self) -> std::optional<std::string> {
    int kind = rng.uniform(0, 2);
    if (kind == 0 && !causes.empty()) {
      int id = rng.pick(causes);
      if (self_is_cause && id == self) return std::nullopt;
      return "Cause[" + std::to_string(id) + "]";
    }
    if (effects.empty()) return std::nullopt;
    int id = rng.pick(effects);
    if (!self_is_cause && id == self) return std::nullopt;
    std::string name = "Effect[" + std::to_string(id) + "]";
    if (kind == 2) name += "[" + std::to_string(rng.uniform(1, static_cast<int>(m.find_effect(id)->tags.size()))) + "]";
    return name;
  };
  for (auto& c : m.causes) {
    if (c.function == CauseFunction::Comment) continue;
    if (c.bypass_tag && rng.chance(opt.p_control_ref))
      if (auto r = reference(true, c.id)) c.bypass_tag = r;
    if (c.inhibit_tag && rng.chance(opt.p_control_ref))
      if (auto r = reference(true, c.id)) c.inhibit_tag = r;
  }
  for (auto& e : m.effects) {
    if (e.function == EffectFunction::Comment) continue;
    if (e.bypass_tag && rng.chance(opt.p_control_ref))
      if (auto r = reference(false, e.id)) e.bypass_tag = r;
    if (e.reset_tag && rng.chance(opt.p_control_ref))
      if (auto r = reference(false, e.id)) e.reset_tag = r;
  }
}

std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
  Rng r(a * 0x9E3779B97F4A7C15ull + b);
  return r.next();
}

}  // namespace

// ---- The generator ----------------------------------------------------------

Matrix random_matrix(std::uint64_t seed, const MatrixOptions& opt) {
  Rng rng(mix(seed, 0x63656d76 /* "cemv" */));
  Matrix m;
  m.name = "RANDOM_" + std::to_string(seed);
  m.title = "Random matrix of seed " + std::to_string(seed);
  m.cycle_ms = opt.cycle_ms ? opt.cycle_ms : kCycles[rng.uniform(0, 7)];
  int ngroups = rng.uniform(0, 4);
  for (int i = 0; i < ngroups; ++i) {
    int g = rng.chance(0.8) ? rng.uniform(1, 8) : rng.uniform(9, kMaxSifGroups);
    m.sif_groups[g] = "Safety function " + std::to_string(g);
  }
  if (rng.chance(opt.p_secure_write)) m.secure_write = SecureWrite{"EN_SWC"};
  if (rng.chance(opt.p_group_deactivation)) m.group_deactivation = GroupDeactivation{"EN_GDM", "SET_GDM"};

  int nc = rng.uniform(opt.min_causes, opt.max_causes);
  int ne = rng.uniform(opt.min_effects, opt.max_effects);
  // Ids are mostly consecutive; small matrices sometimes leave gaps, as edited
  // matrices do.
  int id = 0;
  for (int i = 0; i < nc; ++i) {
    id += 1 + (nc + id < kMaxCauses - 3 && rng.chance(0.1) ? rng.uniform(1, 3) : 0);
    Cause c;
    c.id = id;
    make_cause(rng, opt, m, c, i > 0 && rng.chance(opt.p_comment));
    m.causes.push_back(std::move(c));
  }
  id = 0;
  for (int i = 0; i < ne; ++i) {
    id += 1 + (ne + id < kMaxEffects - 3 && rng.chance(0.1) ? rng.uniform(1, 3) : 0);
    Effect e;
    e.id = id;
    make_effect(rng, opt, m, e, i > 0 && rng.chance(opt.p_comment));
    m.effects.push_back(std::move(e));
  }
  add_intersections(rng, opt, m);
  add_internal_refs(rng, opt, m);
  // A separate stream, so that adding this option left every other field of
  // the matrices of earlier versions unchanged.
  Rng control_rng(mix(seed, 0x6374726c /* "ctrl" */));
  add_control_refs(control_rng, opt, m);
  if (opt.p_simulation_forbidden > 0) {
    Rng simulation_rng(mix(seed, 0x73696d75 /* "simu" */));
    for (auto& c : m.causes)
      for (auto& t : c.tags) t.simulation_allowed = !simulation_rng.chance(opt.p_simulation_forbidden);
    for (auto& e : m.effects)
      for (auto& t : e.tags) t.simulation_allowed = !simulation_rng.chance(opt.p_simulation_forbidden);
  }
  return m;
}

Matrix big_matrix(std::uint64_t seed) {
  MatrixOptions o;
  o.min_causes = o.max_causes = kMaxCauses;
  o.min_effects = o.max_effects = kMaxEffects;
  o.intersections = kMaxIntersections;
  o.cycle_ms = 100;
  o.p_comment = 0.03;
  o.p_secure_write = 1.0;
  o.p_group_deactivation = 1.0;
  o.p_internal_ref = 0.05;
  // The first seed whose matrix uses every option (nearly always the first).
  Matrix m;
  for (std::uint64_t attempt = 0; attempt < 64; ++attempt) {
    m = random_matrix(mix(seed, attempt), o);
    auto counts = feature_counts(m);
    bool all = std::all_of(feature_names().begin(), feature_names().end(),
                           [&](const std::string& f) { return counts[f] > 0; });
    if (all) break;
  }
  m.name = "BIG_" + std::to_string(seed);
  m.title = "128 x 128 matrix with 1024 intersections, every option";
  return m;
}

Matrix square_matrix(int n, std::uint64_t seed) {
  if (n == kMaxCauses) return big_matrix(seed);
  MatrixOptions o;
  o.min_causes = o.max_causes = n;
  o.min_effects = o.max_effects = n;
  o.cycle_ms = 100;
  Matrix best;
  std::size_t best_used = 0;
  for (std::uint64_t attempt = 0; attempt < 64; ++attempt) {
    Matrix m = random_matrix(mix(seed, attempt), o);
    auto counts = feature_counts(m);
    const auto used = static_cast<std::size_t>(std::count_if(
        feature_names().begin(), feature_names().end(), [&](const std::string& f) { return counts[f] > 0; }));
    if (attempt == 0 || used > best_used) {
      best = std::move(m);
      best_used = used;
    }
    if (best_used == feature_names().size()) break;
  }
  best.name = "SQUARE_" + std::to_string(n);
  best.title = std::to_string(n) + " x " + std::to_string(n) + " matrix, every option it can hold";
  return best;
}

// ---- Feature coverage -------------------------------------------------------

const std::vector<std::string>& feature_names() {
  static const std::vector<std::string> names = {
      "input.discrete", "input.analog",
      "function.normal", "function.and", "function.or", "function.2oo3", "function.comment",
      "tag.ett", "tag.dtt", "tag.soft_bypass_not_allowed", "tag.shared", "tag.shared_other_case",
      "analog.high", "analog.low", "analog.hysteresis", "analog.prewarning", "analog.delta",
      "bad_quality.ignore", "bad_quality.trip", "bad_quality.degrade",
      "time.none", "time.on_delay", "time.off_delay", "time.timed",
      "ack.auto", "ack.manual",
      "soft_bypass.not_allowed", "soft_bypass.untimed", "soft_bypass.timed", "soft_bypass.prealarm",
      "cause.bypass_tag", "cause.bypass_tag_shared", "cause.inhibit_tag", "cause.first_out",
      "cause.mutually_locked", "cause.sif",
      "ref.cause", "ref.effect", "ref.effect_tag", "ref.cycle", "ref.control",
      "effect.comment", "effect.ett", "effect.dtt", "effect.multiple_tags", "effect.output_delay",
      "effect.soft_bypass_allowed", "effect.bypass_tag", "effect.reset_tag", "effect.reset_tag_shared",
      "effect.no_reset_tag", "effect.override", "effect.override_prealarm",
      "effect.pass_through", "effect.mask", "effect.pass_through_and_mask",
      "effect.mutually_locked", "effect.sif",
      "intersection.N", "intersection.S", "intersection.V", "intersection.R", "intersection.note",
      "xoon", "xoon.S", "xoon.V_or_R", "xoon.X_below_N",
      "matrix.secure_write", "matrix.group_deactivation", "matrix.id_gap",
  };
  return names;
}

std::map<std::string, int> feature_counts(const Matrix& m) {
  std::map<std::string, int> f;
  for (const auto& n : feature_names()) f[n] = 0;
  std::map<std::string, std::set<std::string>> spellings;  // tag key -> spellings
  std::map<std::string, int> readers;                       // tag key -> causes reading it
  std::map<std::string, int> bypass_users, reset_users;
  int expected_id = 1;
  for (const auto& c : m.causes) {
    if (c.id != expected_id) ++f["matrix.id_gap"];
    expected_id = c.id + 1;
    if (c.function == CauseFunction::Comment) {
      ++f["function.comment"];
      continue;
    }
    ++f[c.input == InputKind::Analog ? "input.analog" : "input.discrete"];
    ++f[std::string("function.") + to_string(c.function)];
    for (const auto& t : c.tags) {
      auto r = parse_internal_ref(t.name);
      if (r) {
        ++f[r->kind == InternalRef::Kind::Cause ? "ref.cause"
            : r->kind == InternalRef::Kind::Effect ? "ref.effect"
                                                   : "ref.effect_tag"];
        Node src{r->kind == InternalRef::Kind::Cause ? Node::Kind::Cause : Node::Kind::Effect, r->id};
        if (reaches(m, Node{Node::Kind::Cause, c.id}, src)) ++f["ref.cycle"];
      } else {
        spellings[tag_key(t.name)].insert(t.name);
        ++readers[tag_key(t.name)];
      }
      if (c.input == InputKind::Discrete) ++f[t.ett ? "tag.ett" : "tag.dtt"];
      if (!t.soft_bypass_allowed) ++f["tag.soft_bypass_not_allowed"];
    }
    if (c.analog) {
      ++f[c.analog->limit_type == LimitType::High ? "analog.high" : "analog.low"];
      if (c.analog->hysteresis > 0) ++f["analog.hysteresis"];
      if (c.analog->prewarning) ++f["analog.prewarning"];
      if (c.analog->delta > 0) ++f["analog.delta"];
    }
    ++f[std::string("bad_quality.") + to_string(c.bad_quality)];
    ++f[std::string("time.") + to_string(c.time.mode)];
    ++f[c.auto_ack ? "ack.auto" : "ack.manual"];
    if (!c.soft_bypass.allowed) ++f["soft_bypass.not_allowed"];
    else ++f[c.soft_bypass.max_s ? "soft_bypass.timed" : "soft_bypass.untimed"];
    if (c.soft_bypass.prealarm_s) ++f["soft_bypass.prealarm"];
    if (c.bypass_tag) {
      ++f["cause.bypass_tag"];
      ++bypass_users[tag_key(*c.bypass_tag)];
    }
    if (c.inhibit_tag) ++f["cause.inhibit_tag"];
    for (const auto* tag : {&c.bypass_tag, &c.inhibit_tag})
      if (*tag && parse_internal_ref(**tag)) ++f["ref.control"];
    if (c.first_out_group) ++f["cause.first_out"];
    if (c.mutually_locked_maintenance) ++f["cause.mutually_locked"];
    if (!c.sif.empty()) ++f["cause.sif"];
  }
  for (const auto& [key, n] : readers) {
    if (n > 1) ++f["tag.shared"];
    if (spellings[key].size() > 1) ++f["tag.shared_other_case"];
  }
  for (const auto& [key, n] : bypass_users)
    if (n > 1) ++f["cause.bypass_tag_shared"];
  expected_id = 1;
  for (const auto& e : m.effects) {
    if (e.id != expected_id) ++f["matrix.id_gap"];
    expected_id = e.id + 1;
    if (e.function == EffectFunction::Comment) {
      ++f["effect.comment"];
      continue;
    }
    for (const auto& t : e.tags) ++f[t.ett ? "effect.ett" : "effect.dtt"];
    if (e.tags.size() > 1) ++f["effect.multiple_tags"];
    if (e.output_delay_ms) ++f["effect.output_delay"];
    if (e.soft_bypass_allowed) ++f["effect.soft_bypass_allowed"];
    if (e.bypass_tag) ++f["effect.bypass_tag"];
    for (const auto* tag : {&e.bypass_tag, &e.reset_tag})
      if (*tag && parse_internal_ref(**tag)) ++f["ref.control"];
    if (e.reset_tag) {
      ++f["effect.reset_tag"];
      ++reset_users[tag_key(*e.reset_tag)];
    } else {
      ++f["effect.no_reset_tag"];
    }
    if (e.override_time) {
      ++f["effect.override"];
      if (e.override_time->prealarm_s) ++f["effect.override_prealarm"];
    }
    if (e.process_data) {
      bool pt = e.process_data->pass_through, mask = e.process_data->mask_tag.has_value();
      if (pt && mask) ++f["effect.pass_through_and_mask"];
      else if (pt) ++f["effect.pass_through"];
      else if (mask) ++f["effect.mask"];
    }
    if (e.mutually_locked_maintenance) ++f["effect.mutually_locked"];
    if (!e.sif.empty()) ++f["effect.sif"];
    int xoon_n = 0, xoon_x = 0;
    IntersectionType xoon_type = IntersectionType::N;
    for (const auto& x : m.intersections)
      if (x.effect == e.id && x.xoon) {
        ++xoon_n;
        xoon_x = *x.xoon;
        xoon_type = x.type;
      }
    if (xoon_n) {
      ++f["xoon"];
      if (xoon_type == IntersectionType::S) ++f["xoon.S"];
      if (xoon_type == IntersectionType::V || xoon_type == IntersectionType::R) ++f["xoon.V_or_R"];
      if (xoon_x < xoon_n) ++f["xoon.X_below_N"];
    }
  }
  for (const auto& [key, n] : reset_users)
    if (n > 1) ++f["effect.reset_tag_shared"];
  for (const auto& x : m.intersections)
    ++f[x.type == IntersectionType::Note ? std::string("intersection.note")
                                         : std::string("intersection.") + to_string(x.type)];
  if (m.secure_write) ++f["matrix.secure_write"];
  if (m.group_deactivation) ++f["matrix.group_deactivation"];
  return f;
}

}  // namespace cemv::testsupport
