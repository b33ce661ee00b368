// Every fitted number of the six quick runs' summaries, recomputed from the CSV it names over the
// window it names, with the library's fit (runner/fits.hpp), to 1e-12 relative; and the window is the
// one the scene asks for. A fitted number no CSV holds the data of is listed by the summary with why.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geomint/observables/ensemble_statistics.hpp"
#include "summary.hpp"

namespace fits_test {


// The value at a dotted path of a JSON object ("a.b.c").
const nlohmann::json& at_path(const nlohmann::json& j, const std::string& path) {
  const nlohmann::json* p = &j;
  for (std::size_t i = 0, e; i <= path.size(); i = e + 1) {
    e = std::min(path.find('.', i), path.size());
    p = &p->at(path.substr(i, e - i));
  }
  return *p;
}

// The fit of one record from its CSV.
double refit(const std::string& experiment, const nlohmann::json& f) {
  const CsvFile t = read_csv(results_dir(experiment) / f["csv"].get<std::string>());
  std::string y = f["y"];
  const bool square = y.ends_with("^2");
  if (square) y.resize(y.size() - 2);
  const std::size_t cx = t.column(f["x"]), cy = t.column(y);
  const double from = f["from"], to = f["to"];
  std::vector<double> xs, ys;
  for (const auto& row : t.rows) {
    const double x = std::stod(row[cx]), v = std::stod(row[cy]);
    if (x >= from && x <= to) xs.push_back(x), ys.push_back(square ? v * v : v);
  }
  if (f["kind"] == "power_law") return geomint::power_law_exponent(xs, ys, from);
  if (f["kind"] == "slope") return geomint::slope_from(xs, ys, from);
  ADD_FAILURE() << "unknown fit kind " << f["kind"];
  return NAN;
}

void expect_fits_recompute(const std::string& experiment, std::size_t at_least) {
  const auto& s = summary_of(experiment);
  ASSERT_TRUE(s.contains("fits")) << experiment << ": no fitted number records its window";
  ASSERT_GE(s["fits"].size(), at_least) << experiment;
  for (const auto& f : s["fits"]) {
    const std::string q = f["quantity"];
    const double value = at_path(s, q).get<double>(), again = refit(experiment, f);
    EXPECT_NEAR(again / value, 1, 1e-12) << experiment << " " << q << ": " << again << " from " << f["csv"] << " over ["
                                         << f["from"] << ", " << f["to"] << "], summary " << value;
    // The window the scene asks for: from = (scene value) * factor * to.
    const double key = at_path(scene_of(experiment), f["from_key"].get<std::string>()).get<double>();
    EXPECT_NEAR(f["from"].get<double>() / (key * f["from_factor"].get<double>() * f["to"].get<double>()), 1, 1e-12)
        << experiment << " " << q << ": the window starts at " << f["from"] << ", the scene's " << f["from_key"] << " is " << key;
  }
  for (const auto& u : s.value("fits_not_recomputable", nlohmann::json::array())) {
    EXPECT_TRUE(u["why"].is_string() && !u["why"].get<std::string>().empty()) << u;
    EXPECT_NO_THROW(at_path(s, u["quantity"].get<std::string>())) << u;
  }
}

// 004 Figs 4 and 6: sigma ~ t^gamma, sigma^2 ~ D t, the growth of H at the processed variables.
TEST(Fits, TiDrift) { expect_fits_recompute("ti_drift", 5); }

}  // namespace fits_test
