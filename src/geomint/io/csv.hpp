#pragma once
// CSV tables: a header row, one observation per row, numbers as %.17g (so a
// double reads back bit for bit).
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace geomint {

class Csv {
 public:
  explicit Csv(std::vector<std::string> columns);

  // One cell at a time, then end_row(); throws std::logic_error on a row of the wrong width.
  Csv& operator<<(double v);
  Csv& operator<<(std::int64_t v);
  Csv& operator<<(int v) { return *this << static_cast<std::int64_t>(v); }
  Csv& operator<<(std::string_view s);
  Csv& operator<<(const char* s) { return *this << std::string_view(s); }
  void end_row();

  template <class... Cells>
  void row(const Cells&... cells) {
    (*this << ... << cells);
    end_row();
  }

  const std::string& str() const { return text_; }
  std::size_t rows() const { return rows_; }

 private:
  void separator();
  std::size_t width_, cells_ = 0, rows_ = 0;
  std::string text_;
};

std::string format_double(double v);  // %.17g; "nan" for every NaN

}  // namespace geomint
