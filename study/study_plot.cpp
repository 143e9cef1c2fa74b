#include "study/study_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/atomic_file.hpp"
#include "core/csv_field.hpp"
#include "core/error.hpp"
#include "plot/line_chart.hpp"

namespace wifislam::study {

namespace {

namespace fs = std::filesystem;

struct MetricSpec {
  const char* column;
  const char* label;  // y axis
  const char* note;   // which way is better
};

// The metrics drawn per level, in figure order.
const std::vector<MetricSpec>& radio_metrics() {
  static const std::vector<MetricSpec> m = {
      {"resolution_m", "signature resolution [m]",
       "beyond it pause pairs stay below wifi_similarity; lower is better"},
      {"far_similar_share", "share of pause pairs > 12 m apart counted similar",
       "lower is better: far look-alikes the Wi-Fi would let through"},
      {"near_similar_share", "share of pause pairs < 4 m apart counted similar",
       "higher is better: the same place recognised"},
      {"aps_heard_per_pause", "access points heard per pause", ""},
      {"clusters", "Wi-Fi clusters along the route", ""}};
  return m;
}

const std::vector<MetricSpec>& slam_metrics() {
  static const std::vector<MetricSpec> m = {
      {"far_wrong_place_closures", "wrong-place loop closures between places > 12 m apart",
       "accepted online; the paper's false loop closures between far look-alikes"},
      {"wrong_place_closures", "wrong-place loop closures", "accepted online"},
      {"false_positive_pct", "false positive loop closures [%]", "wrong place, accepted online"},
      {"ate_rmse_m", "ATE RMSE [m]", "aligned SE(3), lower is better"},
      {"false_negative_pct", "false negatives [% of revisit episodes]", "lower is better"},
      {"far_wrong_place_after_pruning", "far wrong-place closures after pruning",
       "what the back end kept"},
      {"long_term_comparisons", "long-term candidate comparisons", "the work bounding saves"}};
  return m;
}

bool is_seed_axis(const std::string& key) {
  return key == "seed" || (key.size() > 5 && key.compare(key.size() - 5, 5, ".seed") == 0);
}

std::string value_text(const SqlValue& v) {
  if (std::holds_alternative<std::monostate>(v)) return "NULL";
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&v)) return fmt::format("{:g}", *d);
  return std::get<std::string>(v);
}

std::optional<double> number(const SqlValue& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&v)) return *d;
  return std::nullopt;
}

struct AxisColumn {
  std::string key;
  int column = -1;
  std::vector<SqlValue> values;  // distinct, in first-seen order (study order)
  bool numeric = true;
};

/// Median and the band (min-max of the finite values) of one point's cases; +inf stands for NULL
/// (no resolution), so a median that is not finite is no value.
struct PooledValue {
  std::size_t cases = 0;
  double median = 0, lo = 0, hi = 0;
};

PooledValue pool(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  PooledValue p;
  p.cases = values.size();
  const std::size_t n = values.size();
  p.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  p.lo = std::numeric_limits<double>::infinity();
  p.hi = -p.lo;
  for (double v : values)
    if (std::isfinite(v)) p.lo = std::min(p.lo, v), p.hi = std::max(p.hi, v);
  return p;
}

/// The figures of one study database: which axis is x, which split the lines, which are pooled
/// (seeds), then one chart per metric and every point in curves.csv.
class StudyFigures {
 public:
  // A line: the values of the line axes (in study order of their values) and the variant.
  using LineKey = std::pair<std::vector<std::size_t>, std::string>;

  explicit StudyFigures(const ResultTable& table)
      : table_(table), slam_(table.identity.level == "slam") {
    variant_col_ = table.column("variant");
    if (variant_col_ < 0) {
      throw InvalidInputError("study database: the results table has no variant");
    }
    read_axes();
    choose_x_axis();
    choose_line_axes();
  }

  StudyPlotSummary draw(const fs::path& folder) {
    std::string csv = "metric,line,x,cases,median,min,max\n";
    for (const MetricSpec& metric : slam_ ? slam_metrics() : radio_metrics()) {
      const int col = table_.column(metric.column);
      if (col < 0) continue;
      const plot::LineChart chart = metric_chart(metric, col, csv);
      for (const char* extension : {".png", ".svg"}) {
        const fs::path figure = folder / (std::string(metric.column) + extension);
        plot::draw_line_chart(figure, chart);
        summary_.figures.push_back(figure);
      }
    }
    write_file_atomic(folder / "curves.csv", csv);
    return summary_;
  }

 private:
  /// The axes and their distinct values.
  void read_axes() {
    for (const std::string& key : table_.identity.axis_keys) {
      AxisColumn a;
      a.key = key;
      a.column = table_.column(column_name(key));
      if (a.column < 0) throw InvalidInputError("study database: no column for axis " + key);
      for (const auto& row : table_.rows) {
        const SqlValue& v = row[static_cast<std::size_t>(a.column)];
        if (std::find(a.values.begin(), a.values.end(), v) == a.values.end()) {
          a.values.push_back(v);
        }
        a.numeric = a.numeric && number(v).has_value();
      }
      axes_.push_back(std::move(a));
    }
  }

  /// x: a preferred axis, else the first numeric one that varies, else the first that varies.
  void choose_x_axis() {
    for (const char* preferred : {"access_points.count", "appearance.aliasing"}) {
      for (std::size_t i = 0; i < axes_.size() && x_axis_ < 0; ++i)
        if (axes_[i].key == preferred && axes_[i].values.size() > 1) x_axis_ = static_cast<int>(i);
    }
    for (std::size_t i = 0; i < axes_.size() && x_axis_ < 0; ++i)
      if (axes_[i].numeric && axes_[i].values.size() > 1 && !is_seed_axis(axes_[i].key))
        x_axis_ = static_cast<int>(i);
    for (std::size_t i = 0; i < axes_.size() && x_axis_ < 0; ++i)
      if (axes_[i].values.size() > 1 && !is_seed_axis(axes_[i].key)) x_axis_ = static_cast<int>(i);
    summary_.x_axis = x_axis_ >= 0 ? axes_[static_cast<std::size_t>(x_axis_)].key : "";
    categorical_x_ = x_axis_ < 0 || !axes_[static_cast<std::size_t>(x_axis_)].numeric;
    if (!categorical_x_) return;
    if (x_axis_ >= 0) {
      for (const SqlValue& v : axes_[static_cast<std::size_t>(x_axis_)].values)
        categories_.push_back(value_text(v));
    } else {
      categories_.push_back("all cases");
    }
  }

  /// Every other axis that varies splits the lines, except seeds, which are pooled.
  void choose_line_axes() {
    for (std::size_t i = 0; i < axes_.size(); ++i) {
      if (static_cast<int>(i) == x_axis_ || axes_[i].values.size() < 2) continue;
      if (is_seed_axis(axes_[i].key)) {
        summary_.pooled_axes.push_back(axes_[i].key);
      } else {
        line_axes_.push_back(static_cast<int>(i));
        summary_.line_axes.push_back(axes_[i].key);
      }
    }
  }

  double x_of(const std::vector<SqlValue>& row) const {
    if (x_axis_ < 0) return 0.0;
    const AxisColumn& a = axes_[static_cast<std::size_t>(x_axis_)];
    const SqlValue& v = row[static_cast<std::size_t>(a.column)];
    if (!categorical_x_) return *number(v);
    return static_cast<double>(std::find(a.values.begin(), a.values.end(), v) - a.values.begin());
  }

  LineKey line_of(const std::vector<SqlValue>& row) const {
    LineKey key;
    for (int a : line_axes_) {
      const AxisColumn& axis = axes_[static_cast<std::size_t>(a)];
      const SqlValue& v = row[static_cast<std::size_t>(axis.column)];
      key.first.push_back(static_cast<std::size_t>(
          std::find(axis.values.begin(), axis.values.end(), v) - axis.values.begin()));
    }
    key.second = value_text(row[static_cast<std::size_t>(variant_col_)]);
    return key;
  }

  std::string line_label(const LineKey& key) const {
    std::string label;
    for (std::size_t i = 0; i < line_axes_.size(); ++i) {
      const AxisColumn& axis = axes_[static_cast<std::size_t>(line_axes_[i])];
      const std::string short_key = axis.key.substr(axis.key.rfind('.') + 1);
      label += (i ? ", " : "") + short_key + " " + value_text(axis.values[key.first[i]]);
    }
    if (slam_) label += (label.empty() ? "" : ", ") + key.second;
    return label.empty() ? std::string("all cases") : label;
  }

  /// One metric's chart: a series per line, a point per x (median over the pooled cases, band
  /// min-max); its points are appended to `csv`.
  plot::LineChart metric_chart(const MetricSpec& metric, int col, std::string& csv) const {
    // line -> x -> values (+inf for NULL: no resolution)
    std::map<LineKey, std::map<double, std::vector<double>>> points;
    for (const auto& row : table_.rows) {
      const auto v = number(row[static_cast<std::size_t>(col)]);
      points[line_of(row)][x_of(row)].push_back(v ? *v : std::numeric_limits<double>::infinity());
    }
    plot::LineChart chart;
    const std::string pooled =
        summary_.pooled_axes.empty()
            ? std::string("one case per point")
            : fmt::format("median over {}, band from the smallest to the largest",
                          fmt::join(summary_.pooled_axes, ", "));
    chart.title = fmt::format("{}: {}", table_.identity.name, metric.label);
    chart.subtitle = fmt::format("{}{}{}", pooled, *metric.note ? "; " : "", metric.note);
    chart.x_label = x_axis_ >= 0 ? axes_[static_cast<std::size_t>(x_axis_)].key : "";
    chart.y_label = metric.label;
    chart.x_categories = categories_;
    // Colours by the line axes' values, Wi-Fi solid and vanilla dashed in one colour; with no
    // line axis, a colour per variant as well.
    std::map<LineKey, std::int64_t> colour_index;
    for (const auto& [key, by_x] : points) {
      const LineKey colour_key{key.first, line_axes_.empty() ? key.second : std::string()};
      const auto [it, added] =
          colour_index.emplace(colour_key, static_cast<std::int64_t>(colour_index.size()));
      plot::ChartSeries series;
      series.label = line_label(key);
      series.colour = plot::category_colour(it->second);
      series.dashed = key.second == "vanilla";
      for (const auto& [x, values] : by_x) {
        const PooledValue v = pool(values);
        plot::ChartPoint p;
        p.x = x;
        p.y = std::isfinite(v.median) ? v.median : std::numeric_limits<double>::quiet_NaN();
        p.y_lo = std::isfinite(v.median) ? v.lo : p.y;
        p.y_hi = std::isfinite(v.median) ? v.hi : p.y;
        series.points.push_back(p);
        const std::string x_text =
            categorical_x_ ? categories_[static_cast<std::size_t>(x)] : fmt::format("{:g}", x);
        const auto cell = [](double d) { return std::isfinite(d) ? fmt::format("{:g}", d) : ""; };
        csv += fmt::format("{},{},{},{},{},{},{}\n", metric.column,
                           wifislam::csv_field(series.label), wifislam::csv_field(x_text), v.cases,
                           cell(v.median), cell(v.lo), cell(v.hi));
      }
      chart.series.push_back(std::move(series));
    }
    return chart;
  }

  const ResultTable& table_;
  const bool slam_;
  int variant_col_ = -1;
  std::vector<AxisColumn> axes_;
  int x_axis_ = -1;
  bool categorical_x_ = true;
  std::vector<std::string> categories_;
  std::vector<int> line_axes_;
  StudyPlotSummary summary_;
};

}  // namespace

StudyPlotSummary plot_study(const ResultTable& table, const fs::path& folder) {
  return StudyFigures(table).draw(folder);
}

}  // namespace wifislam::study
