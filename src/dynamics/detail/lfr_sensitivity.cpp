#include "lfr_sensitivity.hpp"

#include <utility>
#include <vector>

namespace hyst::detail {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// The entries of one matrix, so that each step walks only its own.
std::vector<MatrixEntryDerivative> entries_of(const LfrPoint& point, LfrMatrix matrix) {
  std::vector<MatrixEntryDerivative> result;
  for (const auto& entry : point.entries)
    if (entry.matrix == matrix) result.push_back(entry);
  return result;
}

// d(M v) += dM v for the entries of M; `into` has a row per parameter, a column per value of M v.
void add_entries(const std::vector<MatrixEntryDerivative>& entries, const double* v,
                 MatrixXd& into) {
  for (const auto& e : entries)
    into(e.parameter, e.row) += e.value * v[e.col];
}

}  // namespace

MatrixXd simulate_with_sensitivities(const LfrPoint& point, Index parameters, const MatrixXd& input,
                                     HystereticLfr<PrandtlIshlinskii>::State start,
                                     const SensitivitySink& sink) {
  const auto& model = point.model;
  const auto& lin = model.linear().params();
  const auto& mats = model.matrices();
  const Index n = lin.a.rows(), m = Index(model.inputs()), p = Index(model.outputs());
  const Index q = Index(model.feedback().size()), P = parameters;
  const auto a_entries = entries_of(point, LfrMatrix::a);
  const auto b_entries = entries_of(point, LfrMatrix::b);
  const auto c_entries = entries_of(point, LfrMatrix::c);
  std::vector<MatrixEntryDerivative> du_entries, dw_entries;  // D's u columns, Dyw
  for (const auto& e : entries_of(point, LfrMatrix::d))
    (e.col < m ? du_entries : dw_entries).push_back(e);
  for (auto& e : dw_entries)
    e.col -= m;

  // Derivatives are stored transposed: one row per parameter, one column per signal value.
  const MatrixXd c_t = lin.c.transpose();
  const MatrixXd b_w_t = mats.b_w.transpose();
  const MatrixXd d_yw_t = mats.d_yw.transpose();
  auto state = model.make_state(start.x, std::move(start.feedback));
  MatrixXd dx = MatrixXd::Zero(P, n), dx_next(P, n);
  MatrixXd dr(P, p + q), dy(P, p), dw(P, q);
  std::vector<MatrixXd> dplay;  // per channel: parameters x plays
  std::vector<std::vector<double>> before;
  for (const auto& pi : model.feedback()) {
    dplay.push_back(MatrixXd::Zero(P, Index(pi.params().thresholds.size())));
    before.emplace_back(pi.params().thresholds.size());
  }
  const MatrixXd u = input.transpose();
  MatrixXd y(p, input.rows());
  VectorXd x(n);

  for (Index k = 0; k < input.rows(); ++k) {
    x = state.x;
    for (Index i = 0; i < q; ++i)
      before[std::size_t(i)] = state.feedback[std::size_t(i)].play;
    model.step(state, {u.col(k).data(), std::size_t(m)}, {y.col(k).data(), std::size_t(p)});

    // r = C x + D [u; 0] (y without w's term, then z).
    dr.noalias() = dx * c_t;
    add_entries(c_entries, x.data(), dr);
    add_entries(du_entries, u.col(k).data(), dr);

    // w_i = sum_l weight_l play_l(z_i).
    for (Index i = 0; i < q; ++i) {
      const auto& pi = model.feedback()[std::size_t(i)].params();
      const double z = state.response[p + i];
      auto& d = dplay[std::size_t(i)];
      for (Index l = 0; l < d.cols(); ++l) {
        const double r = pi.thresholds[std::size_t(l)];
        const double previous = before[std::size_t(i)][std::size_t(l)];
        if (z - r >= previous || z + r <= previous) d.col(l) = dr.col(p + i);
      }
      dw.col(i).noalias() =
          d * Eigen::Map<const VectorXd>(pi.weights.data(), Index(pi.weights.size()));
    }
    for (const auto& g : point.weights)
      dw(g.parameter, g.channel) +=
          state.feedback[std::size_t(g.channel)].play[std::size_t(g.play)];

    // y = r_y + Dyw w.
    dy.noalias() = dr.leftCols(p);
    dy.noalias() += dw * d_yw_t;
    add_entries(dw_entries, state.w.data(), dy);
    if (k >= sink.first) {
      double* row = sink.jacobian + (k - sink.first) * p * P;
      for (Index c = 0; c < p; ++c, row += P)
        Eigen::Map<VectorXd>(row, P) = dy.col(c) * sink.weight[c];
    }

    // x' = A x + B [u; w].
    model.linear().transition().apply_rows(dx, dx_next);
    dx_next.noalias() += dw * b_w_t;
    add_entries(a_entries, x.data(), dx_next);
    add_entries(b_entries, state.drive.data(), dx_next);
    dx.swap(dx_next);
  }
  return y.transpose();
}

}  // namespace hyst::detail
