#pragma once
// Consecutive fit windows over a record of n samples (004 Fig. 2: the local drift of the shifted energy in
// pendulum.slope_windows windows of the run).
#include <cstddef>

namespace geomint {

// Window w (0 <= w < windows, windows <= n) of `windows` consecutive windows over samples 0..n-1: the samples
// [begin, end) = [w per, (w + 1) per), per = floor(n / windows); the last window runs to the end of the record.
struct SampleWindow {
  std::size_t begin, end;
};

inline SampleWindow consecutive_window(std::size_t n, std::size_t windows, std::size_t w) {
  const std::size_t per = n / windows;
  return {w * per, w + 1 == windows ? n : (w + 1) * per};
}

}  // namespace geomint
