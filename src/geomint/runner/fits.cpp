#include "geomint/runner/fits.hpp"

#include "geomint/scene/scene.hpp"

namespace geomint {

double fit_window_start(const Scene& s, const std::string& section, double t_end) {
  return s.real(section + ".fit_from") * t_end;
}

void record_fit(Value& summary, const FitRecord& f) {
  Value where = Value::record();
  for (const auto& [column, value] : f.data.where) where[column] = value;
  Value r = {{"quantity", f.quantity}, {"csv", f.data.csv}, {"x", f.data.x},   {"y", f.data.y},
             {"where", where},         {"kind", f.kind},    {"from", f.from}, {"to", f.to}};
  if (!f.from_key.empty()) r["from_key"] = f.from_key, r["from_factor"] = f.from_factor;
  if (!f.to_key.empty()) r["to_key"] = f.to_key;
  if (f.kind == "order") r["floor"] = f.floor;
  if (!f.data.minus.empty()) r["minus"] = f.data.minus;
  summary["fit_sources"].push_back(std::move(r));
}

void record_order_fit(Value& summary, const std::string& quantity, const FitData& data, const OrderFit& f,
                      double floor) {
  record_fit(summary, {.quantity = quantity, .data = data, .kind = "order", .from = f.h_min, .to = f.h_max, .floor = floor});
}

void record_unfittable(Value& summary, const std::string& quantity, const std::string& why) {
  summary["fits_not_recomputable"].push_back({{"quantity", quantity}, {"why", why}});
}

}  // namespace geomint
