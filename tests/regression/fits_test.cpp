// Every fitted number of the six quick runs' summaries, recomputed from the CSV it names over the
// window it names, with the library's fit (runner/fits.hpp), to 1e-12 relative; and the window is the
// one the scene asks for. A fitted number no CSV holds the data of is listed by the summary with why.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geomint/geometry/volume_series.hpp"
#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/order_fit.hpp"
#include "summary.hpp"

namespace fits_test {

// The value at a dotted path of a JSON object ("a.b.c"; a component of digits indexes an array).
const nlohmann::json& at_path(const nlohmann::json& j, const std::string& path) {
  const nlohmann::json* p = &j;
  for (std::size_t i = 0, e; i <= path.size(); i = e + 1) {
    e = std::min(path.find('.', i), path.size());
    const std::string part = path.substr(i, e - i);
    p = p->is_array() ? &p->at(std::stoul(part)) : &p->at(part);
  }
  return *p;
}

// The fitted number a record names: a summary path, or a CSV cell "file#column#row".
double quantity_of(const std::string& experiment, const nlohmann::json& summary, const std::string& q) {
  const std::size_t a = q.find('#');
  if (a == std::string::npos) return at_path(summary, q).get<double>();
  const std::size_t b = q.find('#', a + 1);
  const CsvFile t = read_csv(results_dir(experiment) / q.substr(0, a));
  return std::stod(t.rows.at(std::stoul(q.substr(b + 1)))[t.column(q.substr(a + 1, b - a - 1))]);
}

// The window's data of one record: x and y (and the `minus` column) of the rows it selects.
struct Window {
  std::vector<double> x, y, minus;
};

Window window_of(const std::string& experiment, const nlohmann::json& f) {
  const CsvFile t = read_csv(results_dir(experiment) / f["csv"].get<std::string>());
  std::string y = f["y"];
  const bool square = y.ends_with("^2");
  if (square) y.resize(y.size() - 2);
  const std::size_t cx = t.column(f["x"]), cy = t.column(y);
  const bool minus = f.contains("minus");
  const std::size_t cm = minus ? t.column(f["minus"]) : 0;
  std::vector<std::pair<std::size_t, std::string>> where;
  for (const auto& [column, value] : f["where"].items()) where.emplace_back(t.column(column), value.get<std::string>());
  const double from = f["from"], to = f["to"];
  Window w;
  for (const auto& row : t.rows) {
    bool selected = true;
    for (const auto& [c, value] : where) selected = selected && row[c] == value;
    const double x = std::stod(row[cx]), v = std::stod(row[cy]);
    if (!selected || x < from || x > to) continue;
    w.x.push_back(x), w.y.push_back(square ? v * v : v);
    if (minus) w.minus.push_back(std::stod(row[cm]));
  }
  return w;
}

// The fit of one record from its CSV.
double refit(const std::string& experiment, const nlohmann::json& f) {
  const Window w = window_of(experiment, f);
  const std::string kind = f["kind"];
  if (kind == "power_law") return geomint::power_law_exponent(w.x, w.y, f["from"]);
  if (kind == "slope") return geomint::slope_from(w.x, w.y, f["from"]);
  if (kind == "order") return geomint::fit_order(w.x, w.y, f["floor"]).order;
  if (kind == "relative_ptp" && w.minus.empty()) return geomint::relative_peak_to_peak(w.y, w.y.size());
  if (kind == "relative_ptp") return geomint::relative_peak_to_peak_minus(w.y, w.minus, w.y.size());
  if (kind == "relative_amplitude") return geomint::relative_amplitude(w.y, w.y.size());
  if (kind == "ptp") return geomint::peak_to_peak(w.y);
  if (kind == "ptp_about_line") return geomint::peak_to_peak_about_line(w.x, w.y);
  if (kind == "ptp_about_quadratic") return geomint::peak_to_peak_about_quadratic(w.x, w.y);
  ADD_FAILURE() << "unknown fit kind " << kind;
  return NAN;
}

void expect_fits_recompute(const std::string& experiment, std::size_t at_least) {
  const auto& s = summary_of(experiment);
  ASSERT_TRUE(s.contains("fit_sources")) << experiment << ": no fitted number records its window";
  ASSERT_GE(s["fit_sources"].size(), at_least) << experiment;
  for (const auto& f : s["fit_sources"]) {
    const std::string q = f["quantity"];
    const double value = quantity_of(experiment, s, q), again = refit(experiment, f);
    if (value == 0) EXPECT_EQ(again, 0) << experiment << " " << q;
    else
      EXPECT_NEAR(again / value, 1, 1e-12) << experiment << " " << q << ": " << again << " from " << f["csv"] << " over ["
                                           << f["from"] << ", " << f["to"] << "], summary " << value;
    // The window the scene asks for: from = (scene value) * factor * to, to = (scene value).
    if (f.contains("from_key")) {
      const double key = at_path(scene_of(experiment), f["from_key"].get<std::string>()).get<double>();
      EXPECT_NEAR(f["from"].get<double>() / (key * f["from_factor"].get<double>() * f["to"].get<double>()), 1, 1e-12)
          << experiment << " " << q << ": the window starts at " << f["from"] << ", the scene's " << f["from_key"] << " is " << key;
    }
    if (f.contains("to_key"))
      EXPECT_EQ(f["to"].get<double>(), at_path(scene_of(experiment), f["to_key"].get<std::string>()).get<double>())
          << experiment << " " << q << ": the window ends at " << f["to"] << ", not at the scene's " << f["to_key"];
  }
  for (const auto& u : s.value("fits_not_recomputable", nlohmann::json::array())) {
    EXPECT_TRUE(u["why"].is_string() && !u["why"].get<std::string>().empty()) << u;
    EXPECT_NO_THROW(at_path(s, u["quantity"].get<std::string>())) << u;
  }
}

// The fitted numbers of each experiment's quick run: orders (each from its convergence CSV), 004's
// exponents, drift rates and local slopes, 003's peak-to-peak volumes over the ptp window.
TEST(Fits, EulerCompensation) { expect_fits_recompute("euler_compensation", 8); }
TEST(Fits, RowlandsConvergence) { expect_fits_recompute("rowlands_convergence", 6); }
TEST(Fits, EnergyMap) { expect_fits_recompute("energy_map", 3); }
TEST(Fits, LobattoTable) { expect_fits_recompute("lobatto_table", 9); }
TEST(Fits, MeasureCloud) { expect_fits_recompute("measure_cloud", 20); }
TEST(Fits, TiDrift) { expect_fits_recompute("ti_drift", 20); }

}  // namespace fits_test
