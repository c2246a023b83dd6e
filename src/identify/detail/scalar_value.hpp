#pragma once
// The value of a fitted quantity without its derivatives: the quantity itself for double, the
// scalar part for ceres::Jet (the fitters' cost functors run on both).

namespace hyst::detail {

inline double value_of(double x) {
  return x;
}

template <class Jet>
double value_of(const Jet& x) {
  return x.a;
}

}  // namespace hyst::detail
