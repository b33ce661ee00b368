#include "geomint/io/csv.hpp"

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

Csv::Csv(std::vector<std::string> columns) : width_(columns.size()) {
  for (std::size_t i = 0; i < columns.size(); ++i) text_ += (i ? "," : "") + columns[i];
  text_ += '\n';
}

void Csv::separator() {
  if (cells_ == width_) throw std::logic_error("Csv: more cells than columns");
  if (cells_++ > 0) text_ += ',';
}

Csv& Csv::operator<<(double v) {
  separator();
  text_ += format_double(v);
  return *this;
}

Csv& Csv::operator<<(std::int64_t v) {
  separator();
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
  cells_ = 0;
  ++rows_;
}

}  // namespace geomint
