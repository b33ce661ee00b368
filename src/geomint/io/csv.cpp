#include "geomint/io/csv.hpp"

#include <algorithm>
#include <cmath>
#include <charconv>
#include <stdexcept>

namespace geomint {

std::string format_double(double v) {
  if (std::isnan(v)) return "nan";  // not "-nan": one spelling for an undefined value
  char buf[32];  // printf's "%.17g", which std::to_chars with a precision is specified to equal, much faster
  const auto end = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17).ptr;
  return std::string(buf, end);
}

Csv::Csv(std::vector<std::string> columns) : columns_(columns), flag_(columns.size(), false), width_(columns.size()) {
  for (std::size_t i = 0; i < columns.size(); ++i) text_ += (i ? "," : "") + columns[i];
  text_ += '\n';
}

Csv& Csv::flags(const std::vector<std::string>& columns) {
  for (const auto& c : columns) {
    const auto at = std::find(columns_.begin(), columns_.end(), c);
    if (at == columns_.end()) throw std::logic_error("Csv: no flag column " + c);
    flag_[static_cast<std::size_t>(at - columns_.begin())] = true;
  }
  return *this;
}

void Csv::separator() {
  if (cells_ == width_) throw std::logic_error("Csv: more cells than columns");
  if (cells_++ > 0) text_ += ',';
}

Csv& Csv::operator<<(double v) {
  separator();
  if (!std::isfinite(v) && row_non_finite_ < 0) row_non_finite_ = static_cast<std::ptrdiff_t>(cells_ - 1);
  if (flag_[cells_ - 1] && v != 0) row_flagged_ = true;
  text_ += format_double(v);
  return *this;
}

Csv& Csv::operator<<(std::int64_t v) {
  separator();
  if (flag_[cells_ - 1] && v != 0) row_flagged_ = true;
  text_ += std::to_string(v);
  return *this;
}

Csv& Csv::operator<<(std::string_view s) {
  if (s.find_first_of(",\n\"") != std::string_view::npos) throw std::logic_error("Csv: cell needs quoting");
  separator();
  text_ += s;
  return *this;
}

void Csv::end_row() {
  if (cells_ != width_) throw std::logic_error("Csv: row has fewer cells than columns");
  text_ += '\n';
  if (row_non_finite_ >= 0 && !row_flagged_ && unflagged_.empty())
    unflagged_ = "row " + std::to_string(rows_ + 1) + ", column " + columns_[static_cast<std::size_t>(row_non_finite_)];
  cells_ = 0, row_non_finite_ = -1, row_flagged_ = false;
  ++rows_;
}

}  // namespace geomint
