#pragma once
// Compensated summation of long sums of small increments.

namespace geomint {

// Compensated summation (Kahan; as in Hairer's GNI codes): s + x with the
// rounding error of earlier additions carried in c, so that long runs do not
// random-walk the round-off.
template <class V>
void compensated_add(V& s, V& c, const V& x) {
  const V y = x - c;
  const V t = s + y;
  c = (t - s) - y;
  s = t;
}

}  // namespace geomint
