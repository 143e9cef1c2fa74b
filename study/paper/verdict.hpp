#pragma once
// How each of the paper's numbers is judged against ours: the rules and their tolerances, stated
// once here (the report prints them from here too, `tolerance_text`).
//
//   reproduced       the same direction as the paper (Wi-Fi against vanilla: less, the same, more),
//                    and the paper's value inside our seeds' range (min-max) or within the
//                    tolerance of our mean;
//   direction only   the same direction, another value;
//   departs          the other direction (or, for a number with no direction, another value);
//   not applicable   we have no measurement for it (the report says why).
//
// What is compared:
//   - a value with a Wi-Fi/vanilla pair (the tables' two columns): the pair's direction, then the
//     value itself;
//   - times (loop-closure time): the Wi-Fi / vanilla ratio, never seconds: the paper's seconds are
//     of 30 fps Kinect datasets on its machine, ours of our twins at our frame rate;
//   - the Wi-Fi overhead: as a share of vanilla's loop-closure time in the same setting; its
//     direction is the paper's claim that it is smaller than the time bounding saves;
//   - a false positive % of vanilla alone: its direction is whether there are any (> floor);
//   - savings and gains ("more than 50 %", "15 % to 25 %", "80 %"): positive is the paper's
//     direction; the bound or range is the value;
//   - counts (frames, keyframes, access points, clusters): the value alone;
//   - a claim of every run ("none", "less than 20" over a part; PaperNumber::every_run): the
//     worst seed, reproduced when it meets the claim (none: at most the floor), else departs.

#include <string>
#include <vector>

#include "study/paper/paper_numbers.hpp"

namespace wifislam::study::paper {

enum class Verdict { kReproduced, kDirectionOnly, kDeparts, kNotApplicable };
const char* to_string(Verdict verdict);  // "reproduced", "direction only", ...

/// Wi-Fi against vanilla.
enum class Direction { kLess, kSame, kMore };
const char* to_string(Direction direction);  // "less", "same", "more"

/// The tolerances. A value agrees when |ours - paper| <= kRelativeTolerance x |paper| + the
/// quantity's absolute floor; a Wi-Fi/vanilla difference is "the same" when it is within
/// kSameFraction of the larger of the two plus that floor (a ratio: within kSameFraction of 1).
inline constexpr double kRelativeTolerance = 0.25;
inline constexpr double kSameFraction = 0.10;
/// 0.02 m for trajectory error, 2 percentage points for %, 0.05 for ratios, 0 for counts.
double absolute_floor(Quantity quantity);
/// The rules above in two sentences, for the report.
std::string tolerance_text();

/// One measurement over seeds (one value per seed; empty when not measured).
struct Measured {
  std::vector<double> per_seed;
  bool empty() const { return per_seed.empty(); }
  double mean() const;
  double sd() const;  // 0 for one seed
  double min() const;
  double max() const;
  /// "0.56 ± 0.02 (0.53-0.59)" or "0.56" for one seed; `decimals` digits.
  std::string text(int decimals) const;
};

struct Judgement {
  Verdict verdict = Verdict::kNotApplicable;
  std::string why;  // the comparison in words: what agreed and what did not
};

/// The paper's value as it states it ("more than 50%", "15%-25%", "0.23 m", "24000").
std::string paper_value_text(const PaperNumber& number);

/// Direction of `wifi` against `vanilla` for a quantity (its floor and kSameFraction).
Direction direction_of(double vanilla, double wifi, Quantity quantity);
/// Direction of a Wi-Fi / vanilla ratio.
Direction direction_of_ratio(double ratio);

/// Whether `ours` agrees with `paper`: inside [min, max], or within tolerance of the mean.
bool value_agrees(double paper, const Measured& ours, Quantity quantity);

/// A number of a Wi-Fi/vanilla pair. `paper_vanilla`/`paper_wifi`: the paper's two values;
/// `our_vanilla`/`our_wifi`: ours per seed (paired by seed); `number` is one of the two.
/// Times are judged on the ratio (see above).
Judgement judge_pair(const PaperNumber& number, double paper_vanilla, double paper_wifi,
                     const Measured& our_vanilla, const Measured& our_wifi);

/// The Wi-Fi overhead: `paper_share` and `our_share` are the overhead over vanilla's loop-closure
/// time (fractions); `paper_below_saving`/`our_below_saving`: whether the overhead is smaller
/// than the loop-closure time Wi-Fi saves (ours: in the mean over seeds).
Judgement judge_overhead(double paper_share, bool paper_below_saving, const Measured& our_share,
                         bool our_below_saving);

/// A number on its own: a count, a vanilla-only %, a saving or a gain (its Bound applies).
Judgement judge_value(const PaperNumber& number, const Measured& ours);

}  // namespace wifislam::study::paper
