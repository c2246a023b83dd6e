#include "lfr_sensitivity.hpp"

#include <utility>
#include <vector>

#include <Eigen/LU>

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

// For a periodic start s0(theta) = F(s0, theta): with Psi = dF/dtheta and Phi = dF/ds0 (rows of
// the end state's derivatives, one per direction), ds0/dtheta = G solves G (I - Phi) = Psi, and
// every scored row gains G times its derivatives by the start. A play that was never pushed keeps
// its start (Phi's identity there, Psi's zero): its value is the history's, not a function of
// theta, so it is left out (G's column zero), as is the whole start when I - Phi is singular.
void add_start_derivatives(const MatrixXd& dx, const std::vector<MatrixXd>& dplay,
                           const std::vector<std::vector<char>>& moved, Index P,
                           const MatrixXd& start_outputs, const SensitivitySink& sink) {
  const Index n = dx.cols(), S = start_outputs.rows();
  std::vector<Index> active;   // the state values that the period map moves
  MatrixXd end(dx.rows(), S);  // d (end state) / d direction, by state value
  end.leftCols(n) = dx;
  for (Index j = 0; j < n; ++j)
    active.push_back(j);
  Index column = n;
  for (std::size_t i = 0; i < dplay.size(); ++i)
    for (Index l = 0; l < dplay[i].cols(); ++l, ++column) {
      end.col(column) = dplay[i].col(l);
      if (moved[i][std::size_t(l)]) active.push_back(column);
    }
  const auto a = Index(active.size());
  MatrixXd system(a, a), psi(P, a);  // (I - Phi) and Psi on the active values
  for (Index c = 0; c < a; ++c) {
    psi.col(c) = end.col(active[std::size_t(c)]).head(P);
    for (Index r = 0; r < a; ++r)
      system(r, c) = (r == c ? 1.0 : 0.0) - end(P + active[std::size_t(r)], active[std::size_t(c)]);
  }
  const Eigen::FullPivLU<MatrixXd> lu(system.transpose());
  if (!lu.isInvertible()) return;
  const MatrixXd g_t = lu.solve(psi.transpose());  // a x P: G^T on the active values
  MatrixXd active_outputs(a, start_outputs.cols());
  for (Index r = 0; r < a; ++r)
    active_outputs.row(r) = start_outputs.row(active[std::size_t(r)]);
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> jacobian(
      sink.jacobian, start_outputs.cols(), P);
  jacobian.noalias() += active_outputs.transpose() * g_t;
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

  // Derivatives are stored transposed: one row per direction, one column per signal value. The
  // directions are the parameters, then, for a periodic start, each state value (x, then every
  // play of every channel): those rows carry the linearised period map.
  Index plays = 0;
  for (const auto& pi : model.feedback())
    plays += Index(pi.params().thresholds.size());
  const Index S = sink.periodic_start ? n + plays : 0, R = P + S;
  const MatrixXd c_t = lin.c.transpose();
  const MatrixXd b_w_t = mats.b_w.transpose();
  const MatrixXd d_yw_t = mats.d_yw.transpose();
  auto state = model.make_state(start.x, std::move(start.feedback));
  MatrixXd dx = MatrixXd::Zero(R, n), dx_next(R, n);
  MatrixXd dr(R, p + q), dy(R, p), dw(R, q);
  std::vector<MatrixXd> dplay;  // per channel: directions x plays
  std::vector<std::vector<double>> before;
  std::vector<std::vector<char>> moved;  // per channel and play: pushed during the run
  for (const auto& pi : model.feedback()) {
    dplay.push_back(MatrixXd::Zero(R, Index(pi.params().thresholds.size())));
    before.emplace_back(pi.params().thresholds.size());
    moved.emplace_back(pi.params().thresholds.size(), char(0));
  }
  if (sink.periodic_start) {
    dx.middleRows(P, n).setIdentity();
    Index row = P + n;
    for (auto& d : dplay)
      for (Index l = 0; l < d.cols(); ++l)
        d(row++, l) = 1.0;
  }
  MatrixXd start_outputs(S, sink.periodic_start ? (input.rows() - sink.first) * p : 0);
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
        if (z - r >= previous || z + r <= previous) {
          d.col(l) = dr.col(p + i);
          moved[std::size_t(i)][std::size_t(l)] = 1;
        }
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
      for (Index c = 0; c < p; ++c, row += P) {
        Eigen::Map<VectorXd>(row, P) = dy.col(c).head(P) * sink.weight[c];
        if (S > 0) start_outputs.col((k - sink.first) * p + c) = dy.col(c).tail(S) * sink.weight[c];
      }
    }

    // x' = A x + B [u; w].
    model.linear().transition().apply_rows(dx, dx_next);
    dx_next.noalias() += dw * b_w_t;
    add_entries(a_entries, x.data(), dx_next);
    add_entries(b_entries, state.drive.data(), dx_next);
    dx.swap(dx_next);
  }
  if (sink.periodic_start) add_start_derivatives(dx, dplay, moved, P, start_outputs, sink);
  return y.transpose();
}

}  // namespace hyst::detail
