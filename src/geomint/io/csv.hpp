#pragma once
// CSV tables: a header row, one observation per row, numbers as %.17g (so a
// double reads back bit for bit). A value that is not finite belongs only in a row that a flag column
// marks (nonzero: diverged, beyond a bound), declared with flags(); the first that is not is kept
// (unflagged_non_finite) and the runner refuses to write the table (runner/experiment.hpp).
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace geomint {

class Csv {
 public:
  explicit Csv(std::vector<std::string> columns);
  // The columns whose nonzero value marks a row in which values may be NaN or infinite.
  Csv& flags(const std::vector<std::string>& columns);
  // "row R, column C" of the first value that is not finite in a row no flag marks, or "".
  const std::string& unflagged_non_finite() const { return unflagged_; }

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
  std::vector<std::string> columns_;
  std::vector<bool> flag_;
  std::size_t width_, cells_ = 0, rows_ = 0;
  std::string text_, unflagged_;
  std::ptrdiff_t row_non_finite_ = -1;  // the column of this row's first value that is not finite
  bool row_flagged_ = false;
};

std::string format_double(double v);  // %.17g; "nan" for every NaN

}  // namespace geomint
