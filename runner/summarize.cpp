#include "runner/summarize.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "metrics/critical_angle.hpp"
#include "metrics/time_series.hpp"
#include "runner/atomic_file.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_record.hpp"
#include "runner/run_summary.hpp"
#include "runner/sweep.hpp"
#include "scenarios/number_text.hpp"
#include "scenarios/source_node.hpp"

namespace rodsort::runner {
namespace {

constexpr const char* kAngleKey = "trap.angle";
constexpr const char* kSeedKey = "seed";
constexpr const char* kSeedsCsvFile = "critical_angle_seeds.csv";

std::optional<double> parse_number(const std::string& text) {
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

/// A number for the table: 3 significant digits, "-" when undefined.
std::string short_number(const std::string& text) {
  const auto value = parse_number(text);
  if (!value || !std::isfinite(*value)) return "-";
  char formatted[32];
  std::snprintf(formatted, sizeof formatted, "%.3g", *value);
  return formatted;
}

/// Prints rows as columns padded to their widest cell.
void print_aligned(std::ostream& out, const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> widths;
  for (const auto& row : rows) {
    widths.resize(std::max(widths.size(), row.size()), 0);
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  }
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      line += row[c];
      if (c + 1 < row.size()) line += std::string(widths[c] - row[c].size() + 2, ' ');
    }
    out << line << '\n';
  }
}

/// Orders groups by their values, key by key: numbers first, in numeric order, then the other
/// values as text (the order of `rodsort plot`'s curves). A total order, so that it can key a map.
struct ValuesBefore {
  bool operator()(const std::vector<std::string>& a, const std::vector<std::string>& b) const {
    const auto rank = [](const std::string& value) {
      const std::optional<double> number = parse_number(value);
      return std::make_tuple(number ? 0 : 1, number.value_or(0.0), value);
    };
    return std::lexicographical_compare(
        a.begin(), a.end(), b.begin(), b.end(),
        [&](const std::string& x, const std::string& y) { return rank(x) < rank(y); });
  }
};

/// The label of a group of points that share every swept value but the angle and the seed.
std::string group_label(const std::vector<std::string>& keys,
                        const std::vector<std::string>& values) {
  std::string label;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (!label.empty()) label += ", ";
    label += keys[k] + "=" + values[k];
  }
  return label.empty() ? "all points" : label;
}

/// The complete points (seeds) at one angle.
struct AngleRuns {
  std::vector<double> etas;
  double levelled_at = 0.0;  ///< the latest time to 90% (NaN once one never got there)
  double duration = std::numeric_limits<double>::infinity();  ///< the shortest run
};

/// angle -> the runs at that angle
using AngleMap = std::map<double, AngleRuns>;

void add_run(AngleRuns& runs, double eta, double levelled_at, double duration) {
  runs.etas.push_back(eta);
  // A run that never reached 90% makes the angle's time NaN for good.
  runs.levelled_at = std::isnan(levelled_at) || std::isnan(runs.levelled_at)
                         ? std::numeric_limits<double>::quiet_NaN()
                         : std::max(runs.levelled_at, levelled_at);
  runs.duration = std::min(runs.duration, duration);
}

/// One point per angle: the mean eta of its runs, with the latest time to 90% and the shortest run.
std::vector<metrics::SweepPoint> sweep_points(const AngleMap& angles) {
  std::vector<metrics::SweepPoint> points;
  for (const auto& [angle, runs] : angles) {
    double sum = 0.0;
    for (const double eta : runs.etas) sum += eta;
    metrics::SweepPoint point{angle, sum / static_cast<double>(runs.etas.size())};
    if (std::isfinite(runs.duration)) {
      point.duration = runs.duration;
      point.levelled_at = runs.levelled_at;
    }
    points.push_back(point);
  }
  return points;
}

/// theta_c of each seed of a group alone and their mean: printed, and one row per seed.
/// Without `reasons_file`, why a seed has no theta_c is printed under the seeds' line.
void report_seeds(const std::vector<std::string>& group, const std::map<double, AngleMap>& seeds,
                  const metrics::SeedCriticalAngles& spread, const char* reasons_file,
                  std::ostream& out, CsvTable& rows) {
  out << "    each seed alone:";
  std::size_t i = 0;
  for (const auto& [seed, angles] : seeds) {
    const metrics::CriticalAngle& critical = spread.per_seed[i++];
    std::vector<std::string> row = group;
    row.push_back(scenarios::format_real(seed));
    char text[64];
    if (critical.found) {
      std::snprintf(text, sizeof text, " %s: %.4g%s", scenarios::format_real(seed).c_str(),
                    critical.angle, critical.caution.empty() ? "" : " (caution)");
      for (const double value :
           {critical.angle, critical.below, critical.above, critical.plateau}) {
        row.push_back(scenarios::format_real(value));
      }
    } else {
      std::snprintf(text, sizeof text, " %s: none", scenarios::format_real(seed).c_str());
      row.insert(row.end(), {"nan", "nan", "nan", "nan"});
    }
    out << text << (i < seeds.size() ? "," : "\n");
    row.push_back(std::to_string(angles.size()));
    row.push_back(critical.found ? (critical.caution.empty() ? "" : "caution: " + critical.caution)
                                 : critical.reason);
    rows.rows.push_back(std::move(row));
  }
  if (!reasons_file) {  // seeds that share a reason on one line, in the order first met
    std::vector<std::pair<std::string, std::string>> reasons;  // reason, its seeds
    i = 0;
    for (const auto& [seed, angles] : seeds) {
      const metrics::CriticalAngle& critical = spread.per_seed[i++];
      if (critical.found) continue;
      auto same = std::find_if(reasons.begin(), reasons.end(),
                               [&](const auto& reason) { return reason.first == critical.reason; });
      if (same == reasons.end()) same = reasons.insert(reasons.end(), {critical.reason, ""});
      same->second += (same->second.empty() ? "" : ", ") + scenarios::format_real(seed);
    }
    for (const auto& [reason, seed_list] : reasons) {
      out << "      seed" << (seed_list.find(',') == std::string::npos ? " " : "s ") << seed_list
          << ": " << reason << '\n';
    }
  }
  char line[200];
  if (spread.found >= 2) {
    std::snprintf(line, sizeof line,
                  "    theta_c = %.4g +- %.2g deg (mean +- standard error over the %d of %zu seeds "
                  "that have one; standard deviation %.2g)\n",
                  spread.mean, spread.standard_error, spread.found, seeds.size(),
                  spread.standard_deviation);
  } else {
    const std::string why_not =
        reasons_file ? "see " + std::string(reasons_file) + " for why not" : "why not: above";
    std::snprintf(line, sizeof line,
                  "    no error bar: %d of %zu seeds alone have a theta_c (%s)\n", spread.found,
                  seeds.size(), why_not.c_str());
  }
  out << line;
}

/// The tables of theta_c: one row per group of points (critical_angle.csv) and one per seed of a
/// group (critical_angle_seeds.csv), each led by the group's values of the other swept keys.
struct CriticalAngleTables {
  CsvTable groups;
  CsvTable seeds;
};

CriticalAngleTables critical_angle_tables(const std::vector<std::string>& group_keys) {
  CriticalAngleTables tables;
  tables.groups.header = group_keys;
  for (const char* column :
       {"theta_c_deg", "below_deg", "above_deg", "plateau_eta", "angles", "note",
        "theta_c_seed_mean_deg", "theta_c_seed_stderr_deg", "seeds_found"}) {
    tables.groups.header.push_back(column);
  }
  tables.seeds.header = group_keys;
  for (const char* column :
       {"seed", "theta_c_deg", "below_deg", "above_deg", "plateau_eta", "angles", "note"}) {
    tables.seeds.header.push_back(column);
  }
  return tables;
}

constexpr const char* kCriticalAngleHeading =
    "\ntheta_c: the angle where eta (mean over seeds) falls through half its low-angle plateau\n";

/// theta_c of one group's seed-averaged curve and, given two seeds or more, of each seed alone:
/// printed under `label`, and a row in each of `tables`.
void report_group(const std::string& label, const std::vector<std::string>& group,
                  const AngleMap& angles, const std::map<double, AngleMap>& seeds,
                  const char* reasons_file, std::ostream& out, CriticalAngleTables& tables) {
  const std::vector<metrics::SweepPoint> points = sweep_points(angles);
  const metrics::CriticalAngle critical = metrics::critical_angle(points);
  std::vector<std::string> row = group;
  char line[256];
  if (critical.found) {
    std::snprintf(line, sizeof line,
                  "  %s: theta_c = %.4g deg (between %.4g and %.4g; plateau eta %.3g)",
                  label.c_str(), critical.angle, critical.below, critical.above, critical.plateau);
    for (const double value : {critical.angle, critical.below, critical.above, critical.plateau}) {
      row.push_back(std::isnan(value) ? "nan" : scenarios::format_real(value));
    }
    row.push_back(std::to_string(points.size()));
    row.push_back(critical.caution.empty() ? "" : "caution: " + critical.caution);
  } else {
    std::snprintf(line, sizeof line, "  %s: not found (%s)", label.c_str(),
                  critical.reason.c_str());
    for (int i = 0; i < 4; ++i) row.push_back("nan");
    row.push_back(std::to_string(points.size()));
    row.push_back(critical.reason);
  }
  out << line << '\n';
  if (critical.found && !critical.caution.empty()) {
    out << "    caution: " << critical.caution << '\n';
  }
  if (seeds.size() >= 2) {
    std::vector<std::vector<metrics::SweepPoint>> per_seed;
    for (const auto& [seed, seed_angles] : seeds) per_seed.push_back(sweep_points(seed_angles));
    const metrics::SeedCriticalAngles spread = metrics::critical_angle_per_seed(per_seed);
    report_seeds(group, seeds, spread, reasons_file, out, tables.seeds);
    for (const double value : {spread.mean, spread.standard_error}) {
      row.push_back(std::isnan(value) ? "nan" : scenarios::format_real(value));
    }
    row.push_back(std::to_string(spread.found) + " of " + std::to_string(per_seed.size()));
  } else {
    row.insert(row.end(), {"nan", "nan", ""});
  }
  tables.groups.rows.push_back(std::move(row));
}

void report_critical_angles(const std::filesystem::path& sweep_directory, const CsvTable& table,
                            const std::vector<std::string>& keys, std::ostream& out) {
  const std::size_t angle_column = *table.column(kAngleKey);
  const std::size_t status_column = *table.column(kSweepStatusColumn);
  const auto eta_column = table.column("eta_mean");
  std::vector<std::string> group_keys;
  std::vector<std::size_t> group_columns;
  for (const std::string& key : keys) {
    if (key == kAngleKey || key == kSeedKey) continue;
    group_keys.push_back(key);
    group_columns.push_back(*table.column(key));
  }
  const auto levelled_column = table.column("eta_time_to_90_s");
  const auto duration_column = table.column("simulated_s");
  const auto number_at = [](const std::vector<std::string>& row,
                            std::optional<std::size_t> column) {
    const auto value = column ? parse_number(row[*column]) : std::nullopt;
    return value ? *value : std::numeric_limits<double>::quiet_NaN();
  };
  // group values -> angle -> its runs; and the same for each seed of the group alone
  std::map<std::vector<std::string>, AngleMap, ValuesBefore> groups;
  std::map<std::vector<std::string>, std::map<double, AngleMap>, ValuesBefore> seed_groups;
  const auto seed_column = table.column(kSeedKey);
  for (const auto& row : table.rows) {
    std::vector<std::string> group;
    for (const std::size_t column : group_columns) group.push_back(row[column]);
    auto& angles = groups[group];
    const auto angle = parse_number(row[angle_column]);
    const double eta = number_at(row, eta_column);
    if (row[status_column] != "complete" || !angle || !std::isfinite(eta)) continue;
    const double levelled_at = number_at(row, levelled_column);
    const double duration = number_at(row, duration_column);
    add_run(angles[*angle], eta, levelled_at, duration);
    const auto seed = seed_column ? parse_number(row[*seed_column]) : std::nullopt;
    if (seed) add_run(seed_groups[group][*seed][*angle], eta, levelled_at, duration);
  }

  CriticalAngleTables tables = critical_angle_tables(group_keys);
  out << kCriticalAngleHeading;
  for (const auto& [group, angles] : groups) {
    report_group(group_label(group_keys, group), group, angles, seed_groups[group], kSeedsCsvFile,
                 out, tables);
  }
  write_file_atomically(sweep_directory / "critical_angle.csv", csv_text(tables.groups));
  if (!tables.seeds.rows.empty()) {
    write_file_atomically(sweep_directory / kSeedsCsvFile, csv_text(tables.seeds));
  }
}

}  // namespace

int summarize_sweep(const std::filesystem::path& sweep_directory, std::ostream& out,
                    std::ostream& err) {
  const std::filesystem::path sweep_csv = sweep_directory / "sweep.csv";
  if (!std::filesystem::exists(sweep_csv)) {
    err << "rodsort: " << sweep_directory.string()
        << " is not a sweep directory (no sweep.csv; `rodsort sweep` writes one)\n";
    return kExitUsage;
  }
  CsvTable table = read_csv(sweep_csv);
  const auto status_column = table.column(kSweepStatusColumn);
  if (table.header.empty() || table.header[0] != kSweepPointColumn || !status_column) {
    err << "rodsort: " << sweep_csv.string() << " is not a sweep table (no point and status "
        << "columns)\n";
    return kExitFailure;
  }
  const std::vector<std::string> keys(table.header.begin() + 1,
                                      table.header.begin() + static_cast<long>(*status_column));
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> values;
  for (const auto& row : table.rows) {
    names.push_back(row[0]);
    values.emplace_back(row.begin() + 1, row.begin() + static_cast<long>(*status_column));
  }
  write_sweep_csv(sweep_directory, keys, names, values);
  table = read_csv(sweep_csv);

  std::vector<std::string> shown = {kSweepPointColumn};
  shown.insert(shown.end(), keys.begin(), keys.end());
  shown.push_back(kSweepStatusColumn);
  const auto print_table = [&](std::vector<std::string> columns) {
    std::vector<std::vector<std::string>> printed = {columns};
    for (const auto& row : table.rows) {
      std::vector<std::string> cells;
      for (const std::string& column : columns) {
        const std::size_t index = *table.column(column);
        const bool numeric = index > *status_column;
        cells.push_back(numeric ? short_number(row[index]) : row[index]);
      }
      printed.push_back(std::move(cells));
    }
    print_aligned(out, printed);
  };
  std::vector<std::string> eta_columns = shown;
  for (const char* column : {"eta_mean", "eta_spread", "eta_trap_mean", "simulated_s"}) {
    if (table.column(column)) eta_columns.push_back(column);
  }
  out << "eta: trapping efficiency averaged over the last half of each run\n";
  print_table(eta_columns);
  // A mixture: each species' fraction inside the trap, the first species' share of the rods
  // inside and of the held ones, and the sorting index.
  if (table.column("sorting_index_mean")) {
    std::vector<std::string> sorting_columns = shown;
    const std::string prefix = "fraction_trap_", suffix = "_mean";
    std::string first_species;
    for (const std::string& column : table.header) {
      if (column.size() <= prefix.size() + suffix.size() || column.rfind(prefix, 0) != 0 ||
          column.compare(column.size() - suffix.size(), suffix.size(), suffix) != 0) {
        continue;
      }
      sorting_columns.push_back(column);
      if (first_species.empty()) {
        first_species = column.substr(prefix.size(), column.size() - prefix.size() - suffix.size());
      }
    }
    for (const std::string& column :
         {"purity_" + first_species + "_mean", "purity_held_" + first_species + "_mean",
          std::string("sorting_index_mean")}) {
      if (table.column(column)) sorting_columns.push_back(column);
    }
    out << "sorting: averaged over the last half of each run (fraction_trap_s: of species s "
           "inside the trap; purity: "
        << first_species << "'s share of the rods inside, and of the held ones)\n";
    print_table(sorting_columns);
  }
  if (table.column(kAngleKey)) report_critical_angles(sweep_directory, table, keys, out);
  return kExitOk;
}

namespace {

/// The window of the eta means: the first of 1, 2, 5 x 10^k s that cuts `duration_s` into at most
/// 10 pieces.
double round_window(double duration_s) {
  for (double decade = 1.0;; decade *= 10.0) {
    for (const double step : {1.0, 2.0, 5.0}) {
      if (duration_s <= 10.0 * step * decade) return step * decade;
    }
  }
}

std::string format(const char* pattern, double value) {
  char text[48];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

/// A number for the CSV: shortest round-trip text, "nan" when undefined.
std::string csv_number(double value) {
  return std::isfinite(value) ? scenarios::format_real(value) : "nan";
}

/// eta and eta_trap averaged over one window of a run.
struct HistoryWindow {
  double from = 0.0;
  double to = 0.0;
  double eta = 0.0;
  double eta_trap = 0.0;  ///< eta again in a run without eta_trap
};

/// What `rodsort summarize` reads from one run's eta(t).
struct RunHistory {
  std::filesystem::path directory;
  RunRecord record;
  std::string status;      ///< run_status: complete, running, stopped, ...
  double reached_s = 0.0;  ///< the last row of metrics.csv (before --until)
  std::size_t rows = 0;    ///< rows read (up to --until)
  bool has_eta = false;
  bool has_trap = false;  ///< a column eta_trap; without it eta stands in for it
  double half_from = 0.0;
  double half_to = 0.0;
  metrics::PlateauStats eta_stats;
  double eta_trap_mean = 0.0;
  double eta_max = 0.0;
  double eta_trap_max = 0.0;
  double eta_trap_last = 0.0;
  double window = 0.0;
  std::vector<HistoryWindow> windows;
  std::vector<metrics::NucleationAttempt> attempts;
};

RunHistory read_history(const std::filesystem::path& run_directory,
                        const RunHistoryOptions& options) {
  RunHistory history;
  history.directory = run_directory;
  history.record = *read_run_record(run_directory);
  history.status = run_status(run_directory, history.record);
  CsvTable table = read_csv(run_directory / kMetricsCsvFile);
  const auto time_column = table.column("t");
  std::vector<double> times = time_column ? table.numbers(*time_column) : std::vector<double>{};
  // metrics.csv goes on after the last checkpoint, which run.json's simulated_s counts.
  history.reached_s = times.empty() ? history.record.simulated_s : times.back();
  if (options.until_s > 0.0) {
    std::size_t kept = 0;
    while (kept < times.size() && times[kept] <= options.until_s) ++kept;
    table.rows.resize(kept);
    times.resize(kept);
  }
  history.rows = times.size();
  const auto eta_column = table.column("eta");
  history.has_eta = eta_column.has_value();
  if (times.empty() || !eta_column) return history;
  const std::vector<double> eta = table.numbers(*eta_column);
  const auto trap_column = table.column("eta_trap");
  history.has_trap = trap_column.has_value();
  const std::vector<double> eta_trap = trap_column ? table.numbers(*trap_column) : eta;

  history.half_from = 0.5 * (times.front() + times.back());
  history.half_to = times.back();
  history.eta_stats = metrics::plateau_stats(times, eta);
  history.eta_trap_mean = metrics::plateau_stats(times, eta_trap).mean;
  history.eta_max = *std::max_element(eta.begin(), eta.end());
  history.eta_trap_max = *std::max_element(eta_trap.begin(), eta_trap.end());
  history.eta_trap_last = eta_trap.back();

  history.window = options.window_s > 0.0 ? options.window_s : round_window(times.back());
  for (double from = 0.0; from < times.back(); from += history.window) {
    HistoryWindow window{from, from + history.window, 0.0, 0.0};
    int count = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (times[i] < window.from || times[i] >= window.to) continue;
      window.eta += eta[i];
      window.eta_trap += eta_trap[i];
      ++count;
    }
    if (count == 0) continue;
    window.eta /= count;
    window.eta_trap /= count;
    history.windows.push_back(window);
  }
  history.attempts = metrics::nucleation_attempts(times, eta_trap, options.rise, options.fall);
  return history;
}

long failed_attempts(const RunHistory& history) {
  return std::count_if(history.attempts.begin(), history.attempts.end(),
                       [](const auto& attempt) { return attempt.failed(); });
}

void print_history(const RunHistory& history, const RunHistoryOptions& options, std::ostream& out) {
  const RunRecord& record = history.record;
  out << history.directory.string() << ": " << record.name << ", " << record.rods
      << " rods, t = " << format("%g", history.reached_s) << " of "
      << format("%g", record.duration_s) << " s, " << history.status << ", "
      << format("%.3g", record.cpu_per_simulated_second()) << " CPU-s per simulated s\n";
  if (options.until_s > 0.0) out << "  up to t = " << format("%g", options.until_s) << " s\n";
  if (history.rows == 0) {
    out << "  no rows in metrics.csv" << (options.until_s > 0.0 ? " up to then\n" : " yet\n");
    return;
  }
  if (!history.has_eta) {
    out << "  no column eta in metrics.csv: a run without a trap has no eta(t)\n";
    return;
  }
  out << "  last half (" << format("%g", history.half_from) << "-" << format("%g", history.half_to)
      << " s): eta " << format("%.3g", history.eta_stats.mean) << " (spread "
      << format("%.2g", history.eta_stats.spread) << ")";
  if (history.has_trap) out << ", eta_trap " << format("%.3g", history.eta_trap_mean);
  out << "; eta first at 90% of it at " << format("%.4g", history.eta_stats.time_to_90) << " s\n";

  out << "  per " << format("%g", history.window) << " s, eta"
      << (history.has_trap ? " / eta_trap" : "") << ":";
  for (const HistoryWindow& window : history.windows) {
    out << "  " << format("%g", window.from) << "-" << format("%g", window.to) << " "
        << format("%.2f", window.eta);
    if (history.has_trap) out << "/" << format("%.2f", window.eta_trap);
  }
  out << "\n";

  const long failed = failed_attempts(history);
  out << "  nucleation attempts (" << (history.has_trap ? "eta_trap" : "eta") << " above "
      << format("%g", options.rise) << ", failed when back below " << format("%g", options.fall)
      << "): " << history.attempts.size() << ", " << failed << " failed\n";
  for (const auto& attempt : history.attempts) {
    out << "    from " << format("%g", attempt.start) << " s, peak " << format("%.2f", attempt.peak)
        << " at " << format("%g", attempt.peak_time) << " s, ";
    if (attempt.failed()) {
      out << "fell back at " << format("%g", attempt.end) << " s\n";
    } else {
      out << "holds at the end (" << format("%.2f", history.eta_trap_last) << ")\n";
    }
  }
}

/// One row per run: what print_history says, and a pair of columns per window (the union of all
/// runs' windows, empty where a run has none).
CsvTable history_table(const std::vector<RunHistory>& histories) {
  std::map<std::pair<double, double>, std::size_t> window_columns;
  for (const RunHistory& history : histories) {
    for (const HistoryWindow& window : history.windows) window_columns[{window.from, window.to}];
  }
  CsvTable table;
  table.header = {"run",
                  "name",
                  "seed",
                  "rods",
                  "reached_s",
                  "duration_s",
                  "status",
                  "cpu_s_per_simulated_s",
                  "read_to_s",
                  "eta_mean",
                  "eta_spread",
                  "eta_trap_mean",
                  "eta_time_to_90_s",
                  "eta_max",
                  "eta_trap_max",
                  "attempts",
                  "failed_attempts",
                  "holds"};
  for (auto& [window, column] : window_columns) {
    column = table.header.size();
    const std::string span =
        scenarios::format_real(window.first) + "-" + scenarios::format_real(window.second);
    table.header.push_back("eta_" + span);
    table.header.push_back("eta_trap_" + span);
  }
  for (const RunHistory& history : histories) {
    const RunRecord& record = history.record;
    std::vector<std::string> row = {history.directory.string(),
                                    record.name,
                                    std::to_string(record.seed),
                                    std::to_string(record.rods),
                                    csv_number(history.reached_s),
                                    csv_number(record.duration_s),
                                    history.status,
                                    csv_number(record.cpu_per_simulated_second())};
    if (history.has_eta && history.rows > 0) {
      const long failed = failed_attempts(history);
      const bool holds = !history.attempts.empty() && !history.attempts.back().failed();
      row.insert(row.end(), {csv_number(history.half_to), csv_number(history.eta_stats.mean),
                             csv_number(history.eta_stats.spread),
                             history.has_trap ? csv_number(history.eta_trap_mean) : "",
                             csv_number(history.eta_stats.time_to_90), csv_number(history.eta_max),
                             history.has_trap ? csv_number(history.eta_trap_max) : "",
                             std::to_string(history.attempts.size()), std::to_string(failed),
                             holds ? "1" : "0"});
    }
    row.resize(table.header.size());
    for (const HistoryWindow& window : history.windows) {  // none without eta(t)
      const std::size_t column = window_columns.at({window.from, window.to});
      row[column] = csv_number(window.eta);
      if (history.has_trap) row[column + 1] = csv_number(window.eta_trap);
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

/// A run's trap angle, and its resolved scenario less what may differ between the runs of one
/// curve of eta against theta: the name, the seed, the angle and the apex placed from it, the run's
/// length, the outputs and what is derived.
struct CurveScenario {
  std::optional<double> angle;  ///< none: no trap, or no resolved scenario
  scenarios::SourceNode rest;
};

CurveScenario curve_scenario(const std::filesystem::path& run_directory) {
  CurveScenario result;
  scenarios::Diagnostics diagnostics;
  auto tree = scenarios::read_yaml_file(run_directory / kResolvedScenarioFile, diagnostics);
  if (!tree || !tree->is_map()) return result;
  scenarios::SourceNode* trap = tree->find("trap");
  if (trap && trap->is_map()) {
    if (const scenarios::SourceNode* angle = trap->find("angle"); angle && angle->is_scalar()) {
      result.angle = parse_number(angle->scalar);
    }
    trap->erase("angle");
    trap->erase("apex");
  }
  if (scenarios::SourceNode* run = tree->find("run")) run->erase("duration");
  for (const char* key : {"name", "seed", "output", "derived"}) tree->erase(key);
  result.rest = std::move(*tree);
  return result;
}

/// The leaves of a tree in file order: each one's key path ("species[0].noise.kick_eps") and its
/// value as it reads in a message. An empty map or sequence is a leaf.
void collect_leaves(const scenarios::SourceNode& node, const std::string& path,
                    std::vector<std::pair<std::string, std::string>>& leaves) {
  if (node.is_map() && !node.entries.empty()) {
    for (const auto& entry : node.entries) {
      collect_leaves(entry.value, path.empty() ? entry.key : path + "." + entry.key, leaves);
    }
  } else if (node.is_sequence() && !node.items.empty()) {
    for (std::size_t i = 0; i < node.items.size(); ++i) {
      collect_leaves(node.items[i], path + "[" + std::to_string(i) + "]", leaves);
    }
  } else {
    leaves.emplace_back(path.empty() ? "(the whole scenario)" : path, node.describe());
  }
}

/// The keys whose values are not the same in every run, in the order first met, and each run's
/// value of each ("absent" where a run lacks the key).
struct Differences {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> values;  ///< per run, per key
};

Differences differences(const std::vector<CurveScenario>& scenarios_of_runs) {
  std::vector<std::string> order;
  std::vector<std::map<std::string, std::string>> runs;
  for (const CurveScenario& scenario : scenarios_of_runs) {
    std::vector<std::pair<std::string, std::string>> leaves;
    collect_leaves(scenario.rest, "", leaves);
    runs.emplace_back();
    for (auto& [key, value] : leaves) {
      if (std::find(order.begin(), order.end(), key) == order.end()) order.push_back(key);
      runs.back().emplace(std::move(key), std::move(value));
    }
  }
  const auto value_of = [](const std::map<std::string, std::string>& run, const std::string& key) {
    const auto found = run.find(key);
    return found == run.end() ? std::string("absent") : found->second;
  };
  Differences result;
  for (const std::string& key : order) {
    const std::string first = value_of(runs.front(), key);
    if (std::any_of(runs.begin(), runs.end(),
                    [&](const auto& run) { return value_of(run, key) != first; })) {
      result.keys.push_back(key);
    }
  }
  for (const auto& run : runs) {
    std::vector<std::string> values;
    for (const std::string& key : result.keys) values.push_back(value_of(run, key));
    result.values.push_back(std::move(values));
  }
  return result;
}

/// Runs may differ in this many keys besides those of a curve and still be grouped by them.
constexpr std::size_t kMaxGroupKeys = 3;

/// Runs made one by one read as the points of curves of eta against theta: one curve, or one per
/// group of values of the few keys where their scenarios differ beyond those of a curve
/// (curve_scenario).
struct RunsCurve {
  std::string not_computed;                      ///< why the runs make no curve; empty if they do
  std::vector<std::string> keys;                 ///< where their scenarios differ
  std::vector<std::vector<std::string>> values;  ///< per run, per key
  std::vector<double> angles;                    ///< per run
  std::vector<bool> counted;  ///< per run: complete (with --until, as far as that)
};

/// std::nullopt when the runs span fewer than two angles: they make no curve, and nothing is said.
std::optional<RunsCurve> runs_curve(const std::vector<RunHistory>& histories,
                                    const RunHistoryOptions& options) {
  std::vector<CurveScenario> scenarios_of_runs;
  std::set<double> angles_seen;
  for (const RunHistory& history : histories) {
    scenarios_of_runs.push_back(curve_scenario(history.directory));
    if (scenarios_of_runs.back().angle) angles_seen.insert(*scenarios_of_runs.back().angle);
  }
  if (angles_seen.size() < 2) return std::nullopt;
  RunsCurve curve;
  for (std::size_t i = 0; i < histories.size(); ++i) {
    if (!scenarios_of_runs[i].angle) {
      curve.not_computed =
          histories[i].directory.string() + " has no trap angle in its " + kResolvedScenarioFile;
      return curve;
    }
    curve.angles.push_back(*scenarios_of_runs[i].angle);
  }
  Differences differ = differences(scenarios_of_runs);
  if (differ.keys.size() > kMaxGroupKeys) {
    std::size_t other = 1;
    while (differ.values[other][0] == differ.values[0][0]) ++other;
    curve.not_computed = "the runs differ in " + std::to_string(differ.keys.size()) +
                         " keys besides trap.angle and seed (runs are grouped by at most " +
                         std::to_string(kMaxGroupKeys) + "); the first: " + differ.keys[0] +
                         " is " + differ.values[0][0] + " in " +
                         histories.front().directory.string() + " and " + differ.values[other][0] +
                         " in " + histories[other].directory.string();
    return curve;
  }
  curve.keys = std::move(differ.keys);
  curve.values = std::move(differ.values);
  for (const RunHistory& history : histories) {
    const bool far_enough =
        options.until_s > 0.0 ? history.reached_s >= options.until_s : history.status == "complete";
    curve.counted.push_back(far_enough && history.has_eta && history.rows > 0);
  }
  return curve;
}

/// The runs a curve leaves out, on one line: "  left out, not complete: DIR DIR".
std::string left_out_line(const std::vector<RunHistory>& histories, const RunsCurve& curve,
                          const RunHistoryOptions& options) {
  std::string line;
  for (std::size_t i = 0; i < histories.size(); ++i) {
    if (!curve.counted[i]) line += " " + histories[i].directory.string();
  }
  if (line.empty()) return line;
  return std::string("left out, ") +
         (options.until_s > 0.0 ? "not as far as --until" : "not complete") + ":" + line;
}

/// theta_c from runs made one by one, as for a sweep over the angle and the seed: when the runs
/// span two angles or more and are of one scenario but for those (curve_scenario), the complete
/// ones (or, with --until, those that got that far) give theta_c of their seed-averaged curve and
/// of each seed alone. Runs that differ elsewhere in a few keys (another noise, say) are grouped by
/// those keys' values, one curve per group, as a sweep over them would be; runs that differ in
/// more are not compared, and the first key where they differ is named.
void report_runs_critical_angle(const std::vector<RunHistory>& histories,
                                const RunHistoryOptions& options, std::ostream& out) {
  const std::optional<RunsCurve> curve = runs_curve(histories, options);
  if (!curve) return;
  out << kCriticalAngleHeading;
  if (!curve->not_computed.empty()) {
    out << "  not computed: " << curve->not_computed << "\n";
    return;
  }
  struct Group {
    AngleMap angles;
    std::map<double, AngleMap> seeds;
  };
  std::map<std::vector<std::string>, Group, ValuesBefore> groups;
  for (std::size_t i = 0; i < histories.size(); ++i) {
    if (!curve->counted[i]) continue;
    const RunHistory& history = histories[i];
    Group& group = groups[curve->values[i]];
    const double seed = static_cast<double>(history.record.seed);
    const double duration = history.half_to;
    add_run(group.angles[curve->angles[i]], history.eta_stats.mean, history.eta_stats.time_to_90,
            duration);
    add_run(group.seeds[seed][curve->angles[i]], history.eta_stats.mean,
            history.eta_stats.time_to_90, duration);
  }
  if (const std::string line = left_out_line(histories, *curve, options); !line.empty()) {
    out << "  " << line << '\n';
  }
  if (groups.empty()) return;
  if (!curve->keys.empty()) {
    out << "  one curve per value of";
    for (std::size_t k = 0; k < curve->keys.size(); ++k) {
      out << (k == 0 ? " " : ", ") << curve->keys[k];
    }
    out << " (the runs differ there)\n";
  }
  CriticalAngleTables tables = critical_angle_tables(curve->keys);
  for (const auto& [values, group] : groups) {
    report_group(curve->keys.empty() ? "these runs" : group_label(curve->keys, values), values,
                 group.angles, group.seeds, nullptr, out, tables);
  }
}

/// Exit 2 with a message for a directory that holds no run.
bool check_run_directories(const std::vector<std::filesystem::path>& run_directories,
                           std::ostream& err) {
  for (const auto& directory : run_directories) {
    if (!read_run_record(directory) || !std::filesystem::exists(directory / kMetricsCsvFile)) {
      err << "rodsort: " << directory.string()
          << " is neither a sweep directory (sweep.csv) nor a run directory (run.json and "
          << kMetricsCsvFile << ")\n";
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<CsvTable> runs_sweep_table(const std::vector<std::filesystem::path>& run_directories,
                                         const RunHistoryOptions& options, std::ostream& err) {
  if (!check_run_directories(run_directories, err)) return std::nullopt;
  std::vector<RunHistory> histories;
  for (const auto& directory : run_directories) {
    histories.push_back(read_history(directory, options));
  }
  const std::optional<RunsCurve> curve = runs_curve(histories, options);
  if (!curve) {
    err << "rodsort: a curve of eta against theta needs runs at two trap angles or more\n";
    return std::nullopt;
  }
  if (!curve->not_computed.empty()) {
    err << "rodsort: no curve of eta against theta: " << curve->not_computed << "\n";
    return std::nullopt;
  }
  CsvTable table;
  table.header = {kSweepPointColumn, kAngleKey};
  table.header.insert(table.header.end(), curve->keys.begin(), curve->keys.end());
  table.header.insert(table.header.end(), {kSeedKey, kSweepStatusColumn, "eta_mean",
                                           "eta_time_to_90_s", "simulated_s"});
  for (std::size_t i = 0; i < histories.size(); ++i) {
    if (!curve->counted[i]) continue;
    const RunHistory& history = histories[i];
    std::vector<std::string> row = {history.directory.filename().string(),
                                    scenarios::format_real(curve->angles[i])};
    row.insert(row.end(), curve->values[i].begin(), curve->values[i].end());
    row.insert(row.end(),
               {std::to_string(history.record.seed), "complete", csv_number(history.eta_stats.mean),
                csv_number(history.eta_stats.time_to_90), csv_number(history.half_to)});
    table.rows.push_back(std::move(row));
  }
  if (const std::string line = left_out_line(histories, *curve, options); !line.empty()) {
    err << "note: " << line << '\n';
  }
  if (table.rows.empty()) {
    err << "rodsort: no run is " << (options.until_s > 0.0 ? "as far as --until" : "complete")
        << ": no curve of eta against theta\n";
    return std::nullopt;
  }
  return table;
}

int summarize_runs(const std::vector<std::filesystem::path>& run_directories,
                   const RunHistoryOptions& options, std::ostream& out, std::ostream& err) {
  if (!(0.0 <= options.fall && options.fall < options.rise)) {
    err << "rodsort: --fall must lie in [0, --rise); got --rise " << options.rise << " and --fall "
        << options.fall << "\n";
    return kExitUsage;
  }
  if (!check_run_directories(run_directories, err)) return kExitUsage;
  if (!options.csv.empty()) {
    const std::filesystem::path folder = options.csv.parent_path();
    if (std::filesystem::is_directory(options.csv) ||
        !(folder.empty() || std::filesystem::is_directory(folder))) {
      err << "rodsort: --csv " << options.csv.string()
          << ": expected a file name in an existing folder\n";
      return kExitUsage;
    }
  }
  std::vector<RunHistory> histories;
  for (const auto& directory : run_directories) {
    histories.push_back(read_history(directory, options));
    print_history(histories.back(), options, out);
  }
  report_runs_critical_angle(histories, options, out);
  if (!options.csv.empty()) {
    write_file_atomically(options.csv, csv_text(history_table(histories)));
    out << "wrote " << options.csv.string() << '\n';
  }
  return kExitOk;
}

}  // namespace rodsort::runner
