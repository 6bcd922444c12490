#include "simhuman/eval/motion_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "simhuman/control/policy/walk_task.h"
#include "simhuman/core/body_joint.h"
#include "simhuman/core/geometry.h"
#include "simhuman/world/model_builder.h"

namespace simhuman::eval {
namespace {

constexpr double kRad2Deg = 180.0 / M_PI;

double Mean(const std::vector<double>& v) {
  if (v.empty()) return NAN;
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

// the q-quantile of v (linear between order statistics); NaN when empty
double Quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  double pos = q * static_cast<double>(v.size() - 1);
  size_t i = static_cast<size_t>(pos);
  if (i + 1 >= v.size()) return v.back();
  return v[i] + (pos - static_cast<double>(i)) * (v[i + 1] - v[i]);
}

double Correlation(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() < 3 || a.size() != b.size()) return NAN;
  double ma = Mean(a), mb = Mean(b), sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  if (saa <= 1e-12 || sbb <= 1e-12) return NAN;
  return sab / std::sqrt(saa * sbb);
}

// x (forward) of `p` relative to the pelvis in the pelvis heading frame
double Forward(const MotionSample& s, const Eigen::Vector3d& p) {
  return std::cos(s.yaw_rad) * (p.x() - s.pelvis.x()) +
         std::sin(s.yaw_rad) * (p.y() - s.pelvis.y());
}

double Horizontal(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

// per frame: inside a steady walking stretch
std::vector<char> SteadyFrames(const std::vector<MotionSample>& f, double dt, double scale) {
  const int n = static_cast<int>(f.size());
  const int k = std::max(1, static_cast<int>(std::lround(0.25 / dt)));
  const double threshold = kWalkingSpeed * std::sqrt(scale);
  std::vector<char> moving(n, 0), steady(n, 0);
  for (int i = 0; i < n; ++i) {
    int a = std::max(0, i - k), b = std::min(n - 1, i + k);
    double span = f[b].time_s - f[a].time_s;
    moving[i] = span > 0 && Horizontal(f[b].pelvis, f[a].pelvis) / span > threshold;
  }
  for (int i = 0; i < n;) {
    if (!moving[i]) {
      ++i;
      continue;
    }
    int j = i;
    while (j + 1 < n && moving[j + 1]) ++j;
    if (f[j].time_s - f[i].time_s >= kMinStretchS)
      std::fill(steady.begin() + i, steady.begin() + j + 1, 1);
    i = j + 1;
  }
  return steady;
}

// swing phases of `foot` entirely inside steady frames: peak knee, mid-swing minimum and peak
// clearance
void AddSwings(const std::vector<MotionSample>& f, const std::vector<char>& steady,
               const std::vector<char>& contact, int foot, std::vector<double>* knee_peak,
               std::vector<double>* clear_min, std::vector<double>* clear_peak) {
  const int n = static_cast<int>(f.size());
  for (int i = 1; i < n; ++i) {
    if (!(contact[i - 1] && !contact[i])) continue;  // lift-off at i
    int j = i;
    while (j < n && !contact[j]) ++j;
    if (j >= n) break;  // not landed before the end
    bool inside = true;
    for (int k = i - 1; k <= j && inside; ++k) inside = steady[k];
    if (inside && j - i >= 2) {
      double kp = 0, peak = -1e9, low = 1e9;
      const int third = std::max(1, (j - i) / 3);
      for (int k = i; k < j; ++k) {
        kp = std::max(kp, f[k].knee_rad[foot]);
        peak = std::max(peak, f[k].foot_low_z[foot]);
        if (k >= i + third && k < j - third) low = std::min(low, f[k].foot_low_z[foot]);
      }
      if (low > 1e8) low = peak;
      knee_peak->push_back(kp * kRad2Deg);
      clear_min->push_back(low);
      clear_peak->push_back(peak);
    }
    i = j;
  }
}

// Where the stand-up ending in seat-off at frame `seat_off` began: the last frame, within
// kLeanLookBackS before it, whose trunk lean is within kLeanOnsetRad of the least lean there
constexpr double kLeanLookBackS = 4.0;
constexpr double kLeanOnsetRad = 3.0 * M_PI / 180;
int LeanOnset(const std::vector<MotionSample>& f, int seat_off) {
  int first = seat_off;
  while (first > 0 && f[seat_off].time_s - f[first - 1].time_s <= kLeanLookBackS) --first;
  double least = f[seat_off].trunk_pitch_rad;
  for (int k = first; k <= seat_off; ++k) least = std::min(least, f[k].trunk_pitch_rad);
  int onset = seat_off;
  for (int k = first; k <= seat_off; ++k) {
    if (f[k].trunk_pitch_rad <= least + kLeanOnsetRad) onset = k;
  }
  return onset;
}

// sit-to-stand rises: duration, foot strikes during them, sinking back
void AddRises(const std::vector<MotionSample>& f, const std::vector<char> contact[2], double scale,
              MotionMetrics* m) {
  const int n = static_cast<int>(f.size());
  std::vector<double> durations, whole, steps;
  int i = 0;
  while (i < n) {
    // a seated stretch, then the first frame standing after it
    while (i < n && f[i].pelvis.z() >= kSeatedPelvis * scale) ++i;
    while (i < n && f[i].pelvis.z() < kStandingPelvis * scale) ++i;
    if (i >= n) break;
    const int up = i;
    // seat-off: the trough before the rise (back from the last seated frame while the pelvis
    // keeps descending, 5 mm of noise allowed), then the last frame within 2 cm of it
    int trough = up;
    while (trough > 0 && f[trough].pelvis.z() >= kSeatedPelvis * scale) --trough;
    while (trough > 0 && f[trough - 1].pelvis.z() <= f[trough].pelvis.z() + 0.005 * scale) {
      --trough;
    }
    const double zmin = f[trough].pelvis.z();
    int start = trough;
    for (int k = trough; k <= up && f[k].pelvis.z() < kSeatedPelvis * scale; ++k) {
      if (f[k].pelvis.z() <= zmin + 0.02 * scale) start = k;
    }
    int strikes = 0;
    double peak = f[start].pelvis.z();
    bool sank = false;
    for (int k = start + 1; k <= up; ++k) {
      for (int s = 0; s < 2; ++s) strikes += contact[s][k] && !contact[s][k - 1];
      peak = std::max(peak, f[k].pelvis.z());
      sank = sank || f[k].pelvis.z() < peak - 0.05 * scale;
    }
    durations.push_back(f[up].time_s - f[start].time_s);
    whole.push_back(f[up].time_s - f[LeanOnset(f, start)].time_s);
    steps.push_back(strikes);
    ++m->rises;
    m->rises_staggered += sank;
    m->rises_clean += !sank && strikes == 0;
    // the next rise needs a new seated stretch
    while (i < n && f[i].pelvis.z() >= kSeatedPelvis * scale) ++i;
  }
  m->rise_s = Mean(durations);
  m->sit_to_stand_s = Mean(whole);
  m->rise_extra_steps = Mean(steps);
}

}  // namespace

MotionMetrics ComputeMotionMetrics(const std::vector<MotionSample>& f, double scale) {
  MotionMetrics m;
  m.scale = scale;
  const int n = static_cast<int>(f.size());
  if (n < 2) return m;
  m.duration_s = f.back().time_s - f.front().time_s;
  const double dt = m.duration_s / (n - 1);
  if (!(dt > 0)) return m;
  const double contact_z = kContactHeight * scale;
  // touching: the foot on the ground now; contact: the stance phase, with hysteresis (it ends
  // only when the foot rises kLiftHeight), so a heel or toe rocking is not a step
  std::vector<char> touching[2], contact[2];
  for (int s = 0; s < 2; ++s) {
    touching[s].resize(n);
    contact[s].resize(n);
    bool on = f[0].foot_low_z[s] < contact_z;
    for (int i = 0; i < n; ++i) {
      touching[s][i] = f[i].foot_low_z[s] < contact_z;
      if (touching[s][i]) on = true;
      if (f[i].foot_low_z[s] > kLiftHeight * scale) on = false;
      contact[s][i] = on;
    }
  }
  // foot skating over every frame pair on the ground
  std::vector<double> skate;
  for (int i = 0; i + 1 < n; ++i) {
    for (int s = 0; s < 2; ++s) {
      if (touching[s][i] && touching[s][i + 1]) {
        skate.push_back(Horizontal(f[i + 1].foot[s], f[i].foot[s]) /
                        (f[i + 1].time_s - f[i].time_s));
      }
    }
  }
  m.foot_skate_mps = Mean(skate);
  AddRises(f, contact, scale, &m);

  const std::vector<char> steady = SteadyFrames(f, dt, scale);
  double dist = 0;
  std::vector<double> stance_knee, trunk, head, shoulder[2], hand_x[2], foot_x[2], jerk2;
  int both = 0, frames = 0;
  for (int i = 0; i < n; ++i) {
    if (!steady[i]) continue;
    ++frames;
    m.walking_s += dt;
    if (i > 0 && steady[i - 1]) {
      dist += Horizontal(f[i].pelvis, f[i - 1].pelvis);
      for (int s = 0; s < 2; ++s) m.foot_strikes += contact[s][i] && !contact[s][i - 1];
    }
    if (i >= 3 && steady[i - 1] && steady[i - 2] && steady[i - 3]) {
      Eigen::Vector3d j3 =
          (f[i].pelvis - 3 * f[i - 1].pelvis + 3 * f[i - 2].pelvis - f[i - 3].pelvis) /
          (dt * dt * dt);
      jerk2.push_back(j3.squaredNorm());
    }
    both += contact[0][i] && contact[1][i];
    trunk.push_back(f[i].trunk_pitch_rad * kRad2Deg);
    head.push_back(f[i].head_pitch_rad * kRad2Deg);
    for (int s = 0; s < 2; ++s) {
      if (contact[s][i]) stance_knee.push_back(f[i].knee_rad[s] * kRad2Deg);
      shoulder[s].push_back(f[i].shoulder_flex_rad[s] * kRad2Deg);
      hand_x[s].push_back(Forward(f[i], f[i].hand[s]));
      foot_x[s].push_back(Forward(f[i], f[i].foot[s]));
    }
  }
  if (frames < 2) {
    m.walking_s = 0;
    m.foot_strikes = 0;
    return m;
  }
  m.speed_mps = dist / m.walking_s;
  m.cadence_spm = 60.0 * m.foot_strikes / m.walking_s;
  if (m.foot_strikes > 0) m.step_length_m = dist / m.foot_strikes;
  m.stance_knee_deg = Mean(stance_knee);
  m.trunk_pitch_deg = Mean(trunk);
  m.head_pitch_deg = Mean(head);
  m.double_support = static_cast<double>(both) / frames;
  if (!jerk2.empty()) m.pelvis_jerk_rms = std::sqrt(Mean(jerk2));
  double swing_deg = 0, swing_m = 0, corr = 0;
  int corr_n = 0;
  for (int s = 0; s < 2; ++s) {
    swing_deg += 0.5 * (Quantile(shoulder[s], 0.95) - Quantile(shoulder[s], 0.05));
    swing_m += 0.5 * (Quantile(hand_x[s], 0.95) - Quantile(hand_x[s], 0.05));
    double c = Correlation(hand_x[s], foot_x[s]);
    if (std::isfinite(c)) {
      corr += c;
      ++corr_n;
    }
  }
  m.arm_swing_deg = swing_deg;
  m.arm_swing_m = swing_m;
  if (corr_n) m.arm_leg_phase_corr = corr / corr_n;
  std::vector<double> knee_peak, clear_min, clear_peak;
  for (int s = 0; s < 2; ++s)
    AddSwings(f, steady, contact[s], s, &knee_peak, &clear_min, &clear_peak);
  m.swings = static_cast<int>(knee_peak.size());
  m.swing_knee_peak_deg = Mean(knee_peak);
  m.swing_clearance_min_m = Mean(clear_min);
  m.swing_clearance_peak_m = Mean(clear_peak);
  return m;
}

const std::vector<MotionNorm>& MotionNorms() {
  static const std::vector<MotionNorm> norms = {
      {"speed_mps", "comfortable walking speed (m/s)", 1.0, 1.6,
       "Bohannon & Andrews 2011 (1.34-1.43 m/s at 20-59 y); issue 21: >= 1.0"},
      {"cadence_spm", "cadence (steps/min)", 95, 125,
       "Perry & Burnfield 2010 (about 113); issue 21"},
      {"step_length_m", "step length (m)", 0.6, 0.8, "Perry & Burnfield 2010 (stride 1.41 m)"},
      {"stance_knee_deg", "mean stance-phase knee flexion (deg)", 0, 20,
       "Perry & Burnfield 2010 (about 15-20 at loading, near 5 in mid and terminal stance)"},
      {"swing_knee_peak_deg", "peak swing-phase knee flexion (deg)", 55, 70,
       "Perry & Burnfield 2010 (about 60)"},
      {"trunk_pitch_deg", "trunk forward lean (deg)", -5, 10, "issue 21: within 10 of upright"},
      {"head_pitch_deg", "head pitch, + down (deg)", -10, 15,
       "Pozzo, Berthoz & Lefort 1990 (head held near level, a few degrees of oscillation)"},
      {"arm_swing_deg", "shoulder flexion-extension range (deg)", 20, 45,
       "Murray, Sepic & Barnard 1967 (about 30 at free speed)"},
      {"arm_leg_phase_corr", "hand vs same-side foot, fore-aft correlation", -1, -0.5,
       "Meyns, Bruijn & Duysens 2013 (arms swing in counter phase to the legs)"},
      {"double_support", "double-support share of walking time", 0.16, 0.30,
       "Perry & Burnfield 2010 (two periods of about 10 % of the cycle)"},
      {"foot_skate_mps", "foot speed on the ground (m/s)", 0, 0.05,
       "a planted foot does not slide; issue 21: <= 0.05"},
      {"swing_clearance_min_m", "mid-swing minimum foot clearance (m)", 0.008, 0.03,
       "Winter 1992 (minimum toe clearance 1.29 +- 0.45 cm)"},
      {"sit_to_stand_s", "sit-to-stand time, start of the forward lean to standing (s)", 1.5, 3.0,
       "issue 21: 1.5-3; Bohannon 2006 (five stand-ups, sitting down between them, in about "
       "11-15 s at 60-89 y)"},
      {"rise_extra_steps", "steps taken while standing up", 0, 0,
       "a person rises with the feet set (issue 21: no stagger or extra step)"},
  };
  return norms;
}

namespace {

// every double field with its JSON key (the order of MotionMetricsJson)
struct DoubleField {
  const char* key;
  double MotionMetrics::*member;
};
constexpr DoubleField kDoubles[] = {
    {"duration_s", &MotionMetrics::duration_s},
    {"walking_s", &MotionMetrics::walking_s},
    {"speed_mps", &MotionMetrics::speed_mps},
    {"cadence_spm", &MotionMetrics::cadence_spm},
    {"step_length_m", &MotionMetrics::step_length_m},
    {"stance_knee_deg", &MotionMetrics::stance_knee_deg},
    {"swing_knee_peak_deg", &MotionMetrics::swing_knee_peak_deg},
    {"trunk_pitch_deg", &MotionMetrics::trunk_pitch_deg},
    {"head_pitch_deg", &MotionMetrics::head_pitch_deg},
    {"arm_swing_deg", &MotionMetrics::arm_swing_deg},
    {"arm_swing_m", &MotionMetrics::arm_swing_m},
    {"arm_leg_phase_corr", &MotionMetrics::arm_leg_phase_corr},
    {"double_support", &MotionMetrics::double_support},
    {"foot_skate_mps", &MotionMetrics::foot_skate_mps},
    {"swing_clearance_min_m", &MotionMetrics::swing_clearance_min_m},
    {"swing_clearance_peak_m", &MotionMetrics::swing_clearance_peak_m},
    {"pelvis_jerk_rms", &MotionMetrics::pelvis_jerk_rms},
    {"rise_s", &MotionMetrics::rise_s},
    {"sit_to_stand_s", &MotionMetrics::sit_to_stand_s},
    {"rise_extra_steps", &MotionMetrics::rise_extra_steps},
};
struct IntField {
  const char* key;
  int MotionMetrics::*member;
};
constexpr IntField kInts[] = {
    {"foot_strikes", &MotionMetrics::foot_strikes},
    {"swings", &MotionMetrics::swings},
    {"rises", &MotionMetrics::rises},
    {"rises_staggered", &MotionMetrics::rises_staggered},
    {"rises_clean", &MotionMetrics::rises_clean},
};

}  // namespace

double MetricValue(const MotionMetrics& m, const std::string& key) {
  for (const DoubleField& f : kDoubles) {
    if (key == f.key) return m.*f.member;
  }
  return NAN;
}

namespace {

// the value an adult of the same build would show (Froude scaling: lengths / s, speeds /
// sqrt(s), rates x sqrt(s)); the norms are adults'
double AdultEquivalent(const MotionMetrics& m, const std::string& key) {
  const double v = MetricValue(m, key), s = m.scale > 0 ? m.scale : 1.0;
  if (key == "speed_mps" || key == "foot_skate_mps") return v / std::sqrt(s);
  if (key == "cadence_spm") return v * std::sqrt(s);
  if (key == "rise_s" || key == "sit_to_stand_s") return v / std::sqrt(s);
  if (key == "step_length_m" || key == "swing_clearance_min_m") return v / s;
  return v;
}

}  // namespace

double NormGap(const MotionNorm& n, double value) {
  if (!std::isfinite(value)) return NAN;
  if (value < n.lo) return n.lo - value;
  if (value > n.hi) return value - n.hi;
  return 0;
}

nlohmann::ordered_json MotionMetricsJson(const MotionMetrics& m) {
  nlohmann::ordered_json j;
  j["scale"] = m.scale;
  for (const DoubleField& f : kDoubles) {
    const double v = m.*f.member;
    if (std::isfinite(v)) {
      j[f.key] = v;
    } else {
      j[f.key] = nullptr;
    }
  }
  for (const IntField& f : kInts) j[f.key] = m.*f.member;
  nlohmann::ordered_json norms = nlohmann::ordered_json::object();
  for (const MotionNorm& n : MotionNorms()) {
    const double v = AdultEquivalent(m, n.key);
    nlohmann::ordered_json e;
    if (std::isfinite(v)) {
      e["value"] = v;
      e["gap"] = NormGap(n, v);
      e["ok"] = NormGap(n, v) == 0;
    } else {
      e["value"] = nullptr;
      e["gap"] = nullptr;
      e["ok"] = nullptr;
    }
    e["lo"] = n.lo;
    e["hi"] = n.hi;
    norms[n.key] = e;
  }
  j["norms"] = norms;
  j["norms_froude_scaled"] = m.scale != 1.0;
  return j;
}

core::StatusOr<MotionMetrics> MotionMetricsFromJson(const nlohmann::json& j) {
  MotionMetrics m;
  try {
    m.scale = j.at("scale").get<double>();
    for (const DoubleField& f : kDoubles) {
      const nlohmann::json& v = j.at(f.key);
      m.*f.member = v.is_null() ? NAN : v.get<double>();
    }
    for (const IntField& f : kInts) m.*f.member = j.at(f.key).get<int>();
  } catch (const nlohmann::json::exception& e) {
    return absl::InvalidArgumentError(std::string("not a motion metrics record: ") + e.what());
  }
  return m;
}

namespace {

// the mean of `member` over `all`, each weighted by `weight(m)`; entries of weight 0 or with an
// undefined (NaN) value are left out; NaN when none counts
template <typename Weight>
double WeightedMean(const std::vector<MotionMetrics>& all, double MotionMetrics::*member,
                    Weight weight) {
  double sum = 0, total = 0;
  for (const MotionMetrics& m : all) {
    const double w = weight(m), v = m.*member;
    if (!(w > 0) || !std::isfinite(v)) continue;
    sum += v * w;
    total += w;
  }
  return total > 0 ? sum / total : NAN;
}

}  // namespace

MotionMetrics MeanMotionMetrics(const std::vector<MotionMetrics>& all) {
  MotionMetrics out;
  if (all.empty()) return out;
  out.scale = all.front().scale;
  for (const MotionMetrics& m : all) {
    out.duration_s += m.duration_s;
    out.walking_s += std::max(0.0, m.walking_s);
    out.foot_strikes += m.foot_strikes;
    out.swings += m.swings;
    out.rises += m.rises;
    out.rises_staggered += m.rises_staggered;
    out.rises_clean += m.rises_clean;
  }
  using M = MotionMetrics;
  const auto by_walking = [](const M& m) { return m.walking_s; };
  for (double M::*f : {&M::speed_mps, &M::cadence_spm, &M::step_length_m, &M::stance_knee_deg,
                       &M::trunk_pitch_deg, &M::head_pitch_deg, &M::arm_swing_deg, &M::arm_swing_m,
                       &M::arm_leg_phase_corr, &M::double_support, &M::pelvis_jerk_rms}) {
    out.*f = WeightedMean(all, f, by_walking);
  }
  const auto by_swings = [](const M& m) { return static_cast<double>(m.swings); };
  for (double M::*f :
       {&M::swing_knee_peak_deg, &M::swing_clearance_min_m, &M::swing_clearance_peak_m}) {
    out.*f = WeightedMean(all, f, by_swings);
  }
  const auto by_rises = [](const M& m) { return static_cast<double>(m.rises); };
  for (double M::*f : {&M::rise_s, &M::sit_to_stand_s, &M::rise_extra_steps}) {
    out.*f = WeightedMean(all, f, by_rises);
  }
  out.foot_skate_mps =
      WeightedMean(all, &M::foot_skate_mps, [](const M& m) { return m.duration_s; });
  return out;
}

std::string MotionNormsReport(const MotionMetrics& m) {
  std::string out;
  char line[200];
  std::snprintf(line, sizeof(line), "  steady walking %.1f s of %.1f s, %d foot strikes%s\n",
                m.walking_s, m.duration_s, m.foot_strikes,
                m.scale != 1.0 ? " (values against the norms are Froude-scaled to an adult)" : "");
  out += line;
  for (const MotionNorm& n : MotionNorms()) {
    const double v = AdultEquivalent(m, n.key);
    const double gap = NormGap(n, v);
    std::string verdict = !std::isfinite(v) ? "no data"
                          : gap == 0        ? "within"
                          : v < n.lo        ? "below by " + std::to_string(gap).substr(0, 5)
                                            : "above by " + std::to_string(gap).substr(0, 5);
    std::snprintf(line, sizeof(line), "  %-22s %8.3f   norm %.3g to %.3g   %s\n", n.key.c_str(), v,
                  n.lo, n.hi, verdict.c_str());
    out += line;
  }
  return out;
}

MotionSample SampleMotion(const mjModel* m, const mjData* d, const world::SimWorld& world,
                          int agent) {
  const world::AgentIndex& a = world.agent(agent);
  MotionSample s;
  s.time_s = d->time;
  auto site = [&](core::BodyJoint j) {
    const mjtNum* p = d->site_xpos + 3 * a.site[static_cast<int>(j)];
    return Eigen::Vector3d(p[0], p[1], p[2]);
  };
  s.pelvis = Eigen::Vector3d(d->xpos[3 * a.pelvis_body], d->xpos[3 * a.pelvis_body + 1],
                             d->xpos[3 * a.pelvis_body + 2]);
  s.yaw_rad = world::PelvisYaw(d, a);
  // forward lean: the body's up axis tipped along the heading
  auto pitch = [&](int body) {
    const mjtNum* R = d->xmat + 9 * body;
    const double fwd = std::cos(s.yaw_rad) * R[2] + std::sin(s.yaw_rad) * R[5];
    return std::atan2(fwd, R[8]);
  };
  s.trunk_pitch_rad = pitch(a.torso_body);
  s.head_pitch_rad = pitch(a.head_body);
  s.foot[0] = site(core::BodyJoint::kLeftFoot);
  s.foot[1] = site(core::BodyJoint::kRightFoot);
  s.hand[0] = site(core::BodyJoint::kLeftHand);
  s.hand[1] = site(core::BodyJoint::kRightHand);
  const std::string prefix = world::AgentPrefix(agent);
  for (int side = 0; side < 2; ++side) {
    const std::string sd = side == 0 ? "left_" : "right_";
    int g = mj_name2id(m, mjOBJ_GEOM, (prefix + sd + "foot_geom").c_str());
    s.foot_low_z[side] = g >= 0 ? control::LowestBoxCornerZ(m, d, {g}) : s.foot[side].z();
    int knee = mj_name2id(m, mjOBJ_JOINT, (prefix + sd + "knee").c_str());
    int sh = mj_name2id(m, mjOBJ_JOINT, (prefix + sd + "shoulder_y").c_str());
    if (knee >= 0) s.knee_rad[side] = d->qpos[m->jnt_qposadr[knee]];
    if (sh >= 0) s.shoulder_flex_rad[side] = d->qpos[m->jnt_qposadr[sh]];
  }
  return s;
}

MotionMetrics TrajectoryMotionMetrics(const world::SimWorld& world, int agent,
                                      const std::vector<double>& time_s,
                                      const std::vector<std::vector<double>>& qpos) {
  const mjModel* m = world.model();
  mjData* d = mj_makeData(m);
  std::vector<MotionSample> frames;
  frames.reserve(qpos.size());
  for (size_t i = 0; i < qpos.size() && i < time_s.size(); ++i) {
    if (static_cast<int>(qpos[i].size()) != m->nq) continue;
    std::copy(qpos[i].begin(), qpos[i].end(), d->qpos);
    d->time = time_s[i];
    mj_kinematics(m, d);
    frames.push_back(SampleMotion(m, d, world, agent));
  }
  mj_deleteData(d);
  return ComputeMotionMetrics(frames, world.agent(agent).scale);
}

}  // namespace simhuman::eval
