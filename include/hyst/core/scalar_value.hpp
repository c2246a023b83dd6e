#pragma once
//! \file
//! The value part of a scalar that may carry derivatives: models, integrators and fit functors run
//! on double and on automatic-differentiation scalars (ceres::Jet, the fitters' dual numbers).

#include <type_traits>

namespace hyst {

//! The number itself, or the `a` member of an automatic-differentiation scalar.
template <class T>
inline double scalar_value(const T& x) {
  if constexpr (std::is_floating_point_v<T>) {
    return x;
  } else {
    return x.a;
  }
}

}  // namespace hyst
