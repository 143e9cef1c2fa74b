#include "study/paper/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

namespace wifislam::study::paper {

namespace {

std::string number_text(double value, Quantity quantity) {
  const std::string unit = unit_of(quantity);
  if (quantity == Quantity::kFrames || quantity == Quantity::kKeyframes ||
      quantity == Quantity::kAccessPoints || quantity == Quantity::kWifiClusters) {
    return fmt::format("{:.0f}", value);
  }
  return fmt::format("{:.3g}{}{}", value, unit == std::string("%") ? "" : " ", unit);
}

bool is_saving(Quantity q) {
  return q == Quantity::kTimeSavingPct || q == Quantity::kErrorReductionPct ||
         q == Quantity::kAccuracyGainPct;
}

Direction sign_of(double value, double floor) {
  if (value > floor) return Direction::kMore;
  if (value < -floor) return Direction::kLess;
  return Direction::kSame;
}

/// Whether `ours` meets the paper's bound (kMoreThan, kLessThan, a range); kEqual and kAbout by
/// value_agrees.
bool meets_bound(const PaperNumber& n, const Measured& ours) {
  const double floor = absolute_floor(n.quantity);
  switch (n.bound) {
    case Bound::kMoreThan:
      return ours.mean() > n.value;
    case Bound::kLessThan:
      return ours.mean() < n.value;
    case Bound::kRange:
    case Bound::kAboutRange:
      return (ours.mean() >= n.value - floor && ours.mean() <= n.value_high + floor) ||
             (ours.max() >= n.value && ours.min() <= n.value_high);
    case Bound::kEqual:
    case Bound::kAbout:
      return value_agrees(n.value, ours, n.quantity);
  }
  return false;
}

}  // namespace

std::string paper_value_text(const PaperNumber& n) {
  if (!n.printed.empty()) {
    const std::string unit = unit_of(n.quantity);
    return n.printed + (unit.empty() || unit == "%" ? unit : " " + unit);
  }
  switch (n.bound) {
    case Bound::kMoreThan:
      return "more than " + number_text(n.value, n.quantity);
    case Bound::kLessThan:
      return "less than " + number_text(n.value, n.quantity);
    case Bound::kRange:
      return fmt::format("{}-{}", number_text(n.value, n.quantity),
                         number_text(n.value_high, n.quantity));
    case Bound::kAboutRange:
      return fmt::format("about {}-{}", number_text(n.value, n.quantity),
                         number_text(n.value_high, n.quantity));
    case Bound::kAbout:
      return "about " + number_text(n.value, n.quantity);
    case Bound::kEqual:
      return number_text(n.value, n.quantity);
  }
  return "";
}

const char* to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::kReproduced:
      return "reproduced";
    case Verdict::kDirectionOnly:
      return "direction only";
    case Verdict::kDeparts:
      return "departs";
    case Verdict::kNotApplicable:
      return "not applicable";
  }
  return "";
}

const char* to_string(Direction direction) {
  switch (direction) {
    case Direction::kLess:
      return "less";
    case Direction::kSame:
      return "same";
    case Direction::kMore:
      return "more";
  }
  return "";
}

double absolute_floor(Quantity quantity) {
  switch (quantity) {
    case Quantity::kAteRmseM:
      return 0.02;
    case Quantity::kLoopClosureTimeS:
    case Quantity::kWifiOverheadS:
      return 0.05;  // times are judged as ratios
    case Quantity::kFrames:
    case Quantity::kKeyframes:
    case Quantity::kAccessPoints:
    case Quantity::kWifiClusters:
      return 0.0;
    default:
      return 2.0;  // percentage points
  }
}

std::string tolerance_text() {
  return fmt::format(
      "A value agrees with the paper's when the paper's lies inside our seeds' range (min-max) "
      "or within {:.0f} % of it plus a floor (0.02 m for trajectory error, 2 percentage points "
      "for %, 0.05 for a ratio, none for counts) of our mean. Wi-Fi is \"the same\" as vanilla "
      "when the two differ by at most {:.0f} % of the larger plus that floor (a ratio: within "
      "{:.0f} % of 1).",
      100 * kRelativeTolerance, 100 * kSameFraction, 100 * kSameFraction);
}

double Measured::mean() const {
  if (per_seed.empty()) return 0.0;
  return std::accumulate(per_seed.begin(), per_seed.end(), 0.0) /
         static_cast<double>(per_seed.size());
}

double Measured::sd() const {
  if (per_seed.size() < 2) return 0.0;
  const double m = mean();
  double ss = 0.0;
  for (double x : per_seed) ss += (x - m) * (x - m);
  return std::sqrt(ss / static_cast<double>(per_seed.size() - 1));
}

double Measured::min() const {
  return per_seed.empty() ? 0.0 : *std::min_element(per_seed.begin(), per_seed.end());
}

double Measured::max() const {
  return per_seed.empty() ? 0.0 : *std::max_element(per_seed.begin(), per_seed.end());
}

std::string Measured::text(int decimals) const {
  if (per_seed.empty()) return "-";
  if (per_seed.size() == 1) return fmt::format("{:.{}f}", per_seed.front(), decimals);
  return fmt::format("{:.{}f} ± {:.{}f} ({:.{}f}-{:.{}f})", mean(), decimals, sd(), decimals, min(),
                     decimals, max(), decimals);
}

Direction direction_of(double vanilla, double wifi, Quantity quantity) {
  const double band =
      kSameFraction * std::max(std::abs(vanilla), std::abs(wifi)) + absolute_floor(quantity);
  return sign_of(wifi - vanilla, band);
}

Direction direction_of_ratio(double ratio) { return sign_of(ratio - 1.0, kSameFraction); }

bool value_agrees(double paper, const Measured& ours, Quantity quantity) {
  if (ours.empty()) return false;
  if (paper >= ours.min() && paper <= ours.max()) return true;
  return std::abs(ours.mean() - paper) <=
         kRelativeTolerance * std::abs(paper) + absolute_floor(quantity);
}

Judgement judge_pair(const PaperNumber& number, double paper_vanilla, double paper_wifi,
                     const Measured& our_vanilla, const Measured& our_wifi) {
  if (our_vanilla.empty() || our_wifi.empty()) {
    return {Verdict::kNotApplicable, "not measured"};
  }
  const bool is_time = number.quantity == Quantity::kLoopClosureTimeS;
  const bool wifi_side = number.variant == Variant::kWifi;
  Direction paper_direction, our_direction;
  bool agrees = false;
  std::string compared;
  if (is_time) {
    // Ratios per seed (runs paired by seed), the paper's from its two seconds.
    Measured ratios;
    for (std::size_t i = 0; i < std::min(our_vanilla.per_seed.size(), our_wifi.per_seed.size());
         ++i) {
      if (our_vanilla.per_seed[i] > 0) {
        ratios.per_seed.push_back(our_wifi.per_seed[i] / our_vanilla.per_seed[i]);
      }
    }
    if (ratios.empty() || paper_vanilla <= 0) return {Verdict::kNotApplicable, "no time measured"};
    const double paper_ratio = paper_wifi / paper_vanilla;
    paper_direction = direction_of_ratio(paper_ratio);
    our_direction = direction_of_ratio(ratios.mean());
    // A ratio's floor is the time quantity's (0.05), not a percentage's.
    agrees = value_agrees(paper_ratio, ratios, number.quantity);
    compared = fmt::format("Wi-Fi/vanilla {:.2f} (paper {:.2f})", ratios.mean(), paper_ratio);
  } else {
    paper_direction = direction_of(paper_vanilla, paper_wifi, number.quantity);
    our_direction = direction_of(our_vanilla.mean(), our_wifi.mean(), number.quantity);
    agrees = value_agrees(wifi_side ? paper_wifi : paper_vanilla,
                          wifi_side ? our_wifi : our_vanilla, number.quantity);
    compared =
        fmt::format("ours {} against {}",
                    number_text((wifi_side ? our_wifi : our_vanilla).mean(), number.quantity),
                    number_text(wifi_side ? paper_wifi : paper_vanilla, number.quantity));
  }
  const std::string directions = fmt::format("Wi-Fi {} than vanilla (paper: {})",
                                             to_string(our_direction), to_string(paper_direction));
  if (our_direction != paper_direction) return {Verdict::kDeparts, directions + "; " + compared};
  if (agrees) return {Verdict::kReproduced, directions + "; " + compared};
  return {Verdict::kDirectionOnly, directions + "; " + compared + ": outside tolerance"};
}

Judgement judge_overhead(double paper_share, bool paper_below_saving, const Measured& our_share,
                         bool our_below_saving) {
  if (our_share.empty()) return {Verdict::kNotApplicable, "not measured"};
  const std::string compared = fmt::format(
      "overhead {:.1f} % of vanilla's loop-closure time (paper {:.1f} %); {} the "
      "time Wi-Fi saves (paper: {})",
      100 * our_share.mean(), 100 * paper_share, our_below_saving ? "below" : "not below",
      paper_below_saving ? "below" : "not below");
  if (our_below_saving != paper_below_saving) return {Verdict::kDeparts, compared};
  Measured percent;
  for (double s : our_share.per_seed) percent.per_seed.push_back(100 * s);
  if (value_agrees(100 * paper_share, percent, Quantity::kOverheadSharePct)) {
    return {Verdict::kReproduced, compared};
  }
  return {Verdict::kDirectionOnly, compared};
}

Judgement judge_value(const PaperNumber& number, const Measured& ours) {
  if (ours.empty()) return {Verdict::kNotApplicable, "not measured"};
  const int decimals = unit_of(number.quantity) == std::string("") ? 0 : 2;
  const std::string compared =
      fmt::format("ours {} against the paper's {}", ours.text(decimals), paper_value_text(number));
  if (number.every_run) {
    // A claim of every run: the worst seed decides (each seed's value is the largest of its
    // runs), so one seed against the claim misses it, whatever the others.
    const double worst = ours.max();
    const bool holds = number.bound == Bound::kLessThan
                           ? worst < number.value
                           : worst <= number.value + absolute_floor(number.quantity);
    const std::string worst_text =
        fmt::format("; the worst seed {}", number_text(worst, number.quantity));
    return {holds ? Verdict::kReproduced : Verdict::kDeparts, compared + worst_text};
  }
  const bool meets = meets_bound(number, ours);
  // The direction is judged first, on our mean, as for a pair: a seed range that reaches the
  // paper's value does not make a mean of the other direction reproduce it.
  if (is_saving(number.quantity)) {
    // The paper's direction: Wi-Fi saves (positive).
    const Direction ours_direction = sign_of(ours.mean(), absolute_floor(number.quantity));
    if (ours_direction != Direction::kMore) {
      return {Verdict::kDeparts, compared + " (Wi-Fi saves nothing)"};
    }
    return {meets ? Verdict::kReproduced : Verdict::kDirectionOnly, compared};
  }
  if (number.quantity == Quantity::kFalsePositivePct && number.variant == Variant::kVanilla) {
    const double floor = absolute_floor(number.quantity);
    const bool paper_some = number.value > floor, ours_some = ours.mean() > floor;
    if (paper_some != ours_some) {
      return {Verdict::kDeparts, compared + (ours_some ? " (ours has some, the paper's none)"
                                                       : " (ours has none, the paper's some)")};
    }
    return {meets ? Verdict::kReproduced : Verdict::kDirectionOnly, compared};
  }
  return {meets ? Verdict::kReproduced : Verdict::kDeparts, compared};
}

}  // namespace wifislam::study::paper
