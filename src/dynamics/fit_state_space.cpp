#include "hyst/dynamics/fit_state_space.hpp"

#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include <ceres/ceres.h>
#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "../identify/detail/convergence.hpp"
#include "../identify/detail/frequency_response_residual.hpp"
#include "hyst/core/error.hpp"
#include "hyst/identify/error_metrics.hpp"

namespace hyst {
namespace {

using detail::Complex;
using detail::FrequencyData;
using detail::LineResidual;
using Eigen::Index;

FrequencyData frequency_data(const BestLinearApproximation& bla, BlaWeighting weighting) {
  FrequencyData data;
  data.response = bla.response;
  data.inputs = Index(bla.inputs());
  data.outputs = Index(bla.outputs());
  for (const std::size_t line : bla.lines)
    data.z.push_back(std::polar(1.0, 2.0 * std::numbers::pi * double(line) / double(bla.samples)));

  const std::vector<Eigen::MatrixXd>* variance = nullptr;
  if (weighting == BlaWeighting::total_variance)
    variance = !bla.total_variance.empty()   ? &bla.total_variance
               : !bla.noise_variance.empty() ? &bla.noise_variance
                                             : nullptr;
  if (weighting == BlaWeighting::noise_variance) {
    if (bla.noise_variance.empty())
      throw Error(
          "state-space fit: weighting by the noise variance needs a BLA of 2 periods or more");
    variance = &bla.noise_variance;
  }
  if (variance == nullptr) {
    double sum = 0.0;
    for (const auto& g : bla.response)
      sum += g.cwiseAbs2().mean();
    const double scale = 1.0 / std::sqrt(sum / double(bla.response.size()));
    data.weight.assign(bla.response.size(),
                       Eigen::MatrixXd::Constant(data.outputs, data.inputs, scale));
    return data;
  }
  // A variance of 0 (noise-free data) would weight its line infinitely: floor it.
  double mean = 0.0;
  for (const auto& v : *variance)
    mean += v.mean() / double(variance->size());
  const double floor = std::max(mean * 1e-12, std::numeric_limits<double>::min());
  for (const auto& v : *variance)
    data.weight.push_back(v.cwiseMax(floor).cwiseSqrt().cwiseInverse());
  return data;
}

//! Real modal form: pairs of complex poles (radius, angle), then real poles.
struct ModalModel {
  std::size_t pairs = 0;
  std::size_t reals = 0;
  std::vector<double> poles;  //!< rho_1, theta_1, ..., rho_pairs, theta_pairs, r_1, ..., r_reals
  Eigen::MatrixXd b;          //!< n x m
  Eigen::MatrixXd c;          //!< p x n
  Eigen::MatrixXd d;          //!< p x m

  std::size_t order() const { return 2 * pairs + reals; }

  Eigen::MatrixXd a() const {
    const Index n = Index(order());
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t i = 0; i < pairs; ++i) {
      const double re = poles[2 * i] * std::cos(poles[2 * i + 1]);
      const double im = poles[2 * i] * std::sin(poles[2 * i + 1]);
      const Index s = Index(2 * i);
      a(s, s) = re;
      a(s, s + 1) = im;
      a(s + 1, s) = -im;
      a(s + 1, s + 1) = re;
    }
    for (std::size_t i = 0; i < reals; ++i)
      a(Index(2 * pairs + i), Index(2 * pairs + i)) = poles[2 * pairs + i];
    return a;
  }
};

//! C (zI - A)^-1 for every point: what G depends on linearly through B (and D).
Eigen::MatrixXcd resolvent_rows(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c, Complex z) {
  Eigen::MatrixXcd shifted = -a.cast<Complex>();
  shifted.diagonal().array() += z;
  // X (zI - A) = C  <=>  (zI - A)^T X^T = C^T
  return shifted.transpose().partialPivLu().solve(c.cast<Complex>().transpose()).transpose();
}

//! B and D minimising the weighted frequency-response error for given A and C (linear least
//! squares, real and imaginary parts stacked).
void fit_b_and_d(const FrequencyData& data, const Eigen::MatrixXd& a, const Eigen::MatrixXd& c,
                 Eigen::MatrixXd& b, Eigen::MatrixXd& d) {
  const Index n = a.rows();
  const Index m = data.inputs;
  const Index p = data.outputs;
  const Index unknowns = n * m + p * m;
  const Index rows = Index(data.z.size()) * p * m * 2;
  Eigen::MatrixXd design = Eigen::MatrixXd::Zero(rows, unknowns);
  Eigen::VectorXd target(rows);
  Index row = 0;
  for (std::size_t k = 0; k < data.z.size(); ++k) {
    const Eigen::MatrixXcd l = resolvent_rows(a, c, data.z[k]);
    for (Index i = 0; i < p; ++i)
      for (Index j = 0; j < m; ++j) {
        const double w = data.weight[k](i, j);
        for (Index r = 0; r < n; ++r) {
          design(row, r * m + j) = w * l(i, r).real();
          design(row + 1, r * m + j) = w * l(i, r).imag();
        }
        design(row, n * m + i * m + j) = w;
        target(row) = w * data.response[k](i, j).real();
        target(row + 1) = w * data.response[k](i, j).imag();
        row += 2;
      }
  }
  const Eigen::VectorXd solution = design.colPivHouseholderQr().solve(target);
  b = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      solution.data(), n, m);
  d = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      solution.data() + n * m, p, m);
}

//! Stage 1 (McKelvey et al. 1996): A and C from the dominant subspace of the z-power-weighted
//! responses once the input part is projected out.
void subspace_a_and_c(const FrequencyData& data, std::size_t order, std::size_t block_rows,
                      Eigen::MatrixXd& a, Eigen::MatrixXd& c) {
  const Index m = data.inputs;
  const Index p = data.outputs;
  const Index q = Index(block_rows);
  const Index lines = Index(data.z.size());
  // Columns: real parts of every line's block, then imaginary parts. Rows: W (q m), then G (q p).
  Eigen::MatrixXd stacked(2 * lines * m, q * (m + p));  // transposed, for a QR (= LQ of H)
  for (Index k = 0; k < lines; ++k) {
    Complex power = 1.0;
    for (Index i = 0; i < q; ++i) {
      const Eigen::MatrixXcd w = power * Eigen::MatrixXcd::Identity(m, m);
      const Eigen::MatrixXcd g = power * data.response[std::size_t(k)];
      for (Index j = 0; j < m; ++j) {
        const Index re = k * m + j;
        const Index im = lines * m + k * m + j;
        for (Index r = 0; r < m; ++r) {
          stacked(re, i * m + r) = w(r, j).real();
          stacked(im, i * m + r) = w(r, j).imag();
        }
        for (Index r = 0; r < p; ++r) {
          stacked(re, q * m + i * p + r) = g(r, j).real();
          stacked(im, q * m + i * p + r) = g(r, j).imag();
        }
      }
      power *= data.z[std::size_t(k)];
    }
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(stacked);
  const Index width = q * (m + p);
  const Eigen::MatrixXd r = qr.matrixQR().topRows(width).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd l22 = r.transpose().bottomRightCorner(q * p, q * p);
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(l22, Eigen::ComputeThinU);
  const Eigen::MatrixXd observability = svd.matrixU().leftCols(Index(order));
  c = observability.topRows(p);
  a = observability.topRows((q - 1) * p)
          .completeOrthogonalDecomposition()
          .solve(observability.bottomRows((q - 1) * p));
}

//! The real modal form of (A, C), its poles moved inside the bound (unstable ones reflected).
ModalModel modal_form(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c, double max_radius) {
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(a);
  if (eigen.info() != Eigen::Success)
    throw Error("state-space fit: the eigenvalues of the subspace model's A did not converge");
  const Index n = a.rows();
  ModalModel modal;
  Eigen::MatrixXd basis(n, n);
  std::vector<Index> real_poles;
  Index column = 0;
  const auto bounded = [max_radius](double radius) {
    return std::min(radius >= 1.0 ? 1.0 / radius : radius, max_radius);
  };
  for (Index i = 0; i < n; ++i) {
    const Complex pole = eigen.eigenvalues()[i];
    if (pole.imag() > 0.0) {
      basis.col(column++) = eigen.eigenvectors().col(i).real();
      basis.col(column++) = eigen.eigenvectors().col(i).imag();
      modal.poles.push_back(bounded(std::abs(pole)));
      modal.poles.push_back(std::arg(pole));
      ++modal.pairs;
    } else if (pole.imag() == 0.0) {
      real_poles.push_back(i);
    }
  }
  for (const Index i : real_poles) {
    basis.col(column++) = eigen.eigenvectors().col(i).real();
    const double pole = eigen.eigenvalues()[i].real();
    modal.poles.push_back(std::copysign(bounded(std::abs(pole)), pole));
    ++modal.reals;
  }
  if (column != n)
    throw Error("state-space fit: the subspace model's poles do not come in conjugate pairs");
  modal.c = c * basis;
  return modal;
}

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct ParameterBlocks {
  std::vector<double> poles, b, c, d;
};

ParameterBlocks to_blocks(const ModalModel& model) {
  const auto flat = [](const Eigen::MatrixXd& matrix) {
    const RowMajor row_major = matrix;
    return std::vector<double>(row_major.data(), row_major.data() + row_major.size());
  };
  return {model.poles, flat(model.b), flat(model.c), flat(model.d)};
}

void from_blocks(const ParameterBlocks& blocks, ModalModel& model) {
  model.poles = blocks.poles;
  model.b = Eigen::Map<const RowMajor>(blocks.b.data(), model.b.rows(), model.b.cols());
  model.c = Eigen::Map<const RowMajor>(blocks.c.data(), model.c.rows(), model.c.cols());
  model.d = Eigen::Map<const RowMajor>(blocks.d.data(), model.d.rows(), model.d.cols());
}

//! Builds the problem of stage 2 on `blocks` (which must outlive it).
void add_residuals(ceres::Problem& problem, const FrequencyData& data, const ModalModel& model,
                   ParameterBlocks& blocks, double max_radius) {
  for (std::size_t line = 0; line < data.z.size(); ++line)
    problem.AddResidualBlock(new LineResidual(data, line, model.pairs, model.reals), nullptr,
                             blocks.poles.data(), blocks.b.data(), blocks.c.data(),
                             blocks.d.data());
  double* poles = blocks.poles.data();
  for (std::size_t i = 0; i < model.pairs; ++i) {
    problem.SetParameterLowerBound(poles, int(2 * i), 0.0);
    problem.SetParameterUpperBound(poles, int(2 * i), max_radius);
    problem.SetParameterLowerBound(poles, int(2 * i + 1), 0.0);
    problem.SetParameterUpperBound(poles, int(2 * i + 1), std::numbers::pi);
  }
  for (std::size_t i = 0; i < model.reals; ++i) {
    problem.SetParameterLowerBound(poles, int(2 * model.pairs + i), -max_radius);
    problem.SetParameterUpperBound(poles, int(2 * model.pairs + i), max_radius);
  }
}

double weighted_cost(const FrequencyData& data, const ModalModel& model) {
  ceres::Problem problem;
  ParameterBlocks blocks = to_blocks(model);
  add_residuals(problem, data, model, blocks, 1.0);
  double cost = 0.0;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr);
  return cost;
}

//! The error of the model's responses against the BLA's, on real and imaginary parts.
ErrorMetrics response_error(const FrequencyData& data, const StateSpace& model,
                            const BestLinearApproximation& bla) {
  const auto fitted = model.frequency_response(bla.frequencies());
  std::vector<double> measured;
  std::vector<double> predicted;
  for (std::size_t k = 0; k < fitted.size(); ++k)
    for (Index i = 0; i < data.outputs; ++i)
      for (Index j = 0; j < data.inputs; ++j) {
        measured.push_back(data.response[k](i, j).real());
        measured.push_back(data.response[k](i, j).imag());
        predicted.push_back(fitted[k](i, j).real());
        predicted.push_back(fitted[k](i, j).imag());
      }
  return error_metrics(measured, predicted);
}

void check_options(const BestLinearApproximation& bla, const StateSpaceFitOptions& options,
                   std::size_t block_rows) {
  if (bla.response.empty()) throw Error("state-space fit: the BLA has no line");
  if (options.order < 1 || options.order > kMaxStateSpaceFitOrder)
    throw Error(
        fmt::format("state-space fit: order {} must be in 1..{} (the limit of a fit's "
                    "order)",
                    options.order, kMaxStateSpaceFitOrder));
  if (block_rows <= options.order)
    throw Error(fmt::format("state-space fit: subspace block rows q = {} must exceed the order {}",
                            block_rows, options.order));
  if (block_rows * bla.outputs() < options.order)
    throw Error(fmt::format("state-space fit: q p = {} rows cannot hold order {}",
                            block_rows * bla.outputs(), options.order));
  if (2 * bla.lines.size() * bla.inputs() < block_rows * (bla.inputs() + bla.outputs()))
    throw Error(fmt::format(
        "state-space fit: {} lines are too few for order {} (q = {} needs at least {})",
        bla.lines.size(), options.order, block_rows,
        (block_rows * (bla.inputs() + bla.outputs()) + 2 * bla.inputs() - 1) / (2 * bla.inputs())));
  if (!(options.max_pole_radius > 0.0 && options.max_pole_radius < 1.0))
    throw Error(fmt::format("state-space fit: max_pole_radius {} must be in (0, 1)",
                            options.max_pole_radius));
}

}  // namespace

BlaWeighting bla_weighting_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<BlaWeighting>, "BLA weighting", "weighting");
}

StateSpaceFit fit_state_space(const BestLinearApproximation& bla,
                              const StateSpaceFitOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const std::size_t block_rows =
      options.subspace_block_rows != 0 ? options.subspace_block_rows : 2 * options.order + 2;
  check_options(bla, options, block_rows);
  const auto tell = [&](std::size_t done, std::string_view step) {
    if (options.progress) options.progress(Progress{"state-space fit", done, 2, step});
  };
  const FrequencyData data = frequency_data(bla, options.weighting);

  tell(0, "subspace");
  Eigen::MatrixXd a;
  Eigen::MatrixXd c;
  subspace_a_and_c(data, options.order, block_rows, a, c);
  ModalModel modal = modal_form(a, c, options.max_pole_radius);
  fit_b_and_d(data, modal.a(), modal.c, modal.b, modal.d);
  const double subspace_cost = weighted_cost(data, modal);

  tell(1, "Levenberg-Marquardt");
  ParameterBlocks blocks = to_blocks(modal);
  ceres::Problem problem;
  add_residuals(problem, data, modal, blocks, options.max_pole_radius);
  ceres::Solver::Options solver =
      detail::levenberg_marquardt_options(options.max_iterations, detail::kFunctionTolerance);
  solver.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  solver.num_threads = 2;
  detail::StagnationStop stagnation;
  solver.callbacks.push_back(&stagnation);
  ceres::Solver::Summary summary;
  if (options.max_iterations > 0) ceres::Solve(solver, &problem, &summary);
  from_blocks(blocks, modal);

  StateSpace model(StateSpace::Params{modal.a(), modal.b, modal.c, modal.d, bla.sample_time});
  FitReport report;
  report.model = "state_space";
  report.method = fmt::format(
      "frequency-domain subspace (q = {}), then Levenberg-Marquardt on the {}-weighted "
      "frequency response (Ceres)",
      block_rows, to_string(options.weighting));
  report.termination = options.max_iterations == 0 ? Termination::converged
                       : stagnation.stopped()      ? Termination::converged
                                                   : detail::termination_of_ceres(summary);
  report.message = options.max_iterations == 0 ? "the subspace model, not refined"
                   : stagnation.stopped()      ? stagnation.message()
                                               : summary.message;
  report.iterations = std::size_t(summary.iterations.size());
  report.initial_cost = subspace_cost;
  report.final_cost = options.max_iterations == 0 ? subspace_cost : summary.final_cost;
  report.parameters = blocks.poles.size() + blocks.b.size() + blocks.c.size() + blocks.d.size();
  report.fit = response_error(data, model, bla);
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  tell(2, "done");
  return {std::move(model), std::move(report), subspace_cost};
}

}  // namespace hyst
