#pragma once
// The regressor matrix of a linear fit (one row per sample, one column per weight), the largest
// allocation of a fit: a size the machine cannot hold is an error that names it, instead of a
// bare std::bad_alloc from Eigen (which allocates with malloc and throws itself).

#include <new>
#include <string_view>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "hyst/core/error.hpp"

namespace hyst::detail {

//! An uninitialised rows x columns matrix; hyst::Error "<fit>: the regressor matrix of 200000
//! samples x 50000 weights (80 GB) does not fit in memory" when the allocation fails.
inline Eigen::MatrixXd regressor_matrix(Eigen::Index rows, Eigen::Index columns,
                                        std::string_view fit) {
  try {
    return Eigen::MatrixXd(rows, columns);
  } catch (const std::bad_alloc&) {
    const double bytes = static_cast<double>(rows) * static_cast<double>(columns) * sizeof(double);
    throw Error(
        fmt::format("{}: the regressor matrix of {} samples x {} weights ({:.3g} GB) does "
                    "not fit in memory",
                    fit, rows, columns, bytes / 1e9));
  }
}

}  // namespace hyst::detail
