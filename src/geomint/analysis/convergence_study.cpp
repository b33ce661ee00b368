#include "geomint/analysis/convergence_study.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "geomint/core/numerical_failure.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/summary.hpp"

namespace geomint {

ConvergenceStudy::ConvergenceStudy(ConvergenceRuns runs)
    : csv_(std::move(runs.csv)), orders_csv_(std::move(runs.orders_csv)), h_(std::move(runs.h)),
      steps_(std::move(runs.steps)), initials_(std::max<std::size_t>(runs.initials, 1)), initial_column_(runs.initials > 0) {
  if (h_.size() != steps_.size()) throw std::logic_error("ConvergenceStudy " + csv_ + ": h and steps differ in length");
}

ConvergenceStudy& ConvergenceStudy::column(const std::string& name,
                                           const std::function<double(std::size_t, std::size_t)>& value) {
  Column c{name, std::vector<std::vector<double>>(initials_)};
  for (std::size_t i = 0; i < initials_; ++i)
    for (std::size_t j = 0; j < h_.size(); ++j) c.by_initial[i].push_back(value(i, j));
  columns_.push_back(std::move(c));
  return *this;
}

ConvergenceStudy& ConvergenceStudy::column(const std::string& name, const std::vector<double>& by_h) {
  if (initials_ != 1 || by_h.size() != h_.size())
    throw std::logic_error("ConvergenceStudy column " + name + ": one value per step of one initial condition");
  return column(name, [&](std::size_t, std::size_t j) { return by_h[j]; });
}

ConvergenceStudy& ConvergenceStudy::flag(const std::string& name,
                                         const std::function<bool(std::size_t, std::size_t)>& marked) {
  flags_.push_back(name);
  return column(name, [&](std::size_t i, std::size_t j) { return marked(i, j) ? 1.0 : 0.0; });
}

ConvergenceStudy& ConvergenceStudy::fit(const std::string& name, const std::string& column, double floor,
                                        const std::string& floor_is) {
  return fit(name, column, [floor](std::size_t) { return floor; }, floor_is);
}

ConvergenceStudy& ConvergenceStudy::fit(const std::string& name, const std::string& column,
                                        const std::function<double(std::size_t)>& floor_of,
                                        const std::string& floor_is) {
  return fit(name, column, OrderFitRule{.floor = floor_of, .floor_is = floor_is});
}

ConvergenceStudy& ConvergenceStudy::fit(const std::string& name, const std::string& column, const OrderFitRule& rule) {
  const Column& c = column_named(column);
  for (std::size_t i = 0; i < initials_; ++i) {
    const double floor = rule.floor(i);
    std::vector<double> err = c.by_initial[i];  // (outside the window: not a point of the fit)
    for (std::size_t j = 0; j < h_.size(); ++j)
      if (h_[j] > rule.h_max) err[j] = std::numeric_limits<double>::quiet_NaN();
    try {
      fits_.push_back({i, name, column, fit_order(h_, err, floor, name.c_str()), floor});
    } catch (const NumericalFailure& e) {
      if (!rule.required) {
        fits_.push_back({i, name, column, std::nullopt, floor});
        continue;
      }
      const std::string initial = initial_column_ ? "initial condition " + std::to_string(i) + ", " : "";
      throw NumericalFailure(std::string(e.what()) + " (" + initial + "floor " + format_double(floor) +
                             ": below it the errors are " + rule.floor_is + "; add larger h)");
    }
  }
  return *this;
}

const ConvergenceStudy::Column& ConvergenceStudy::column_named(const std::string& name) const {
  const auto it = std::find_if(columns_.begin(), columns_.end(), [&](const Column& c) { return c.name == name; });
  if (it == columns_.end()) throw std::logic_error("ConvergenceStudy " + csv_ + ": no column " + name);
  return *it;
}

const std::vector<double>& ConvergenceStudy::values(const std::string& column, std::size_t i) const {
  return column_named(column).by_initial.at(i);
}

const OrderFit& ConvergenceStudy::order(const std::string& name, std::size_t i) const {
  for (const auto& f : fits_)
    if (f.initial == i && f.name == name && f.fit) return *f.fit;
  throw std::logic_error("ConvergenceStudy " + csv_ + ": no order " + name + " of initial condition " + std::to_string(i));
}

bool ConvergenceStudy::has_order(const std::string& name, std::size_t i) const {
  for (const auto& f : fits_)
    if (f.initial == i && f.name == name) return f.fit.has_value();
  return false;
}

Value ConvergenceStudy::orders(std::size_t i) const {
  Value out = Value::record();
  for (const auto& f : fits_)
    if (f.initial == i) out[f.name] = f.fit ? Value(f.fit->order) : Value();
  return out;
}

Value ConvergenceStudy::fits(std::size_t i) const {
  Value out = Value::record();
  for (const auto& f : fits_)
    if (f.initial == i && f.fit) out[f.name] = to_value(*f.fit);
  return out;
}

std::vector<const ConvergenceStudy::Fit*> ConvergenceStudy::fits_by_initial() const {
  std::vector<const Fit*> out;
  for (const auto& f : fits_) out.push_back(&f);
  std::stable_sort(out.begin(), out.end(), [](const Fit* a, const Fit* b) { return a->initial < b->initial; });
  return out;
}

Csv ConvergenceStudy::csv() const {
  std::vector<std::string> names;
  if (initial_column_) names.emplace_back("initial");
  names.insert(names.end(), {"h", "steps"});
  for (const auto& c : columns_) names.push_back(c.name);
  Csv out(names);
  out.flags(flags_);
  for (std::size_t i = 0; i < initials_; ++i)
    for (std::size_t j = 0; j < h_.size(); ++j) {
      if (initial_column_) out << static_cast<std::int64_t>(i);
      out << h_[j] << steps_[j];
      for (const auto& c : columns_) out << c.by_initial[i][j];
      out.end_row();
    }
  return out;
}

Csv ConvergenceStudy::orders_csv() const {
  Csv out({"initial", "name", "order", "log10_c", "r2", "points", "h_min", "h_max"});
  for (const Fit* f : fits_by_initial())
    if (f->fit)
      out.row(static_cast<std::int64_t>(f->initial), f->name, f->fit->order, f->fit->log10_c, f->fit->r2, f->fit->points,
              f->fit->h_min, f->fit->h_max);
  return out;
}

void ConvergenceStudy::write(Context& ctx) const {
  ctx.write(csv_, csv());
  ctx.write(orders_csv_, orders_csv());
  for (const Fit* f : fits_by_initial()) {
    if (!f->fit) continue;  // ("no order": nothing fitted to recompute)
    if (initial_column_)
      record_order_fit(ctx.summary, "orders_by_initial." + std::to_string(f->initial) + "." + f->name,
                       {csv_, "h", f->column, {{"initial", std::to_string(f->initial)}}}, *f->fit, f->floor);
    else
      record_order_fit(ctx.summary, "orders." + f->name, {csv_, "h", f->column}, *f->fit, f->floor);
  }
  merge(ctx.summary, "orders", orders(0));
  if (initial_column_) {
    Value by_initial = Value::list();
    for (std::size_t i = 0; i < initials_; ++i) by_initial.push_back(orders(i));
    ctx.summary["orders_by_initial"] = by_initial;
  }
  merge(ctx.summary, "fits", fits(0));
}

}  // namespace geomint
