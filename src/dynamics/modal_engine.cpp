// The modal engine: steps the decoupled modes of a SecondOrderSystem (simulator_engine.h).
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "simulator_engine.h"
#include "tracked_vehicle_dynamics/dynamics/discrete_modes.h"
#include "tracked_vehicle_dynamics/dynamics/discretization.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/output_layout.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

void checkTruncation(const SimulatorOptions& options) {
  if (!(options.max_mode_frequency_hz >= 0) || !std::isfinite(options.max_mode_frequency_hz))
    throw InputError(
        "Simulator: max_mode_frequency_hz must be finite and >= 0 (0 keeps every mode)");
}

namespace {

// Per mode r: [eta; eta']_{k+1} = Phi_r [eta; eta']_k + g0_r p_k + g1_r p_{k+1} + (g0_r + g1_r) p_g
// with p = Psi w, Psi = [Phi^T K_u, Phi^T C_u], p_g = Phi^T f_g (constant: exact for both holds).
// Outputs: H Phi eta, H Phi eta', H Phi eta'' with eta'' = p + p_g - omega^2 eta - d eta'.
//
// Everything the road inputs drive is one linear map of w, stacked as G (input_map_):
//   g = G w = [p; y_t; y_t'],  y_t, y_t' the quasi-static output terms (constructor).
// G has (modes + outputs) x inputs entries, so g = G w is most of the work of a step. A road input
// changes only where the terrain under its contact is not flat, so g is updated by increments,
//   g_{k+1} = g_k + sum over changed inputs j of G(:, j) (w_{k+1,j} - w_{k,j}),
// and recomputed in full (re-anchored: no drift) every kAnchorSteps steps, or when the changes
// are dense, where the full product is the cheaper one. Exact either way up to rounding.
// step(): the inputs are numbered along the track, so a stretch of rough terrain changes a few
// runs of neighbouring columns; each run is one product G(:, a..b) dw(a..b) (a ramp under the
// tracked vehicle: ~100 of 360 inputs change, in ~10 runs, a third of the full product's work).
// simulate(): blocks of samples whose changes are dense (more than 1/kDenseFraction of the
// inputs per sample) take a matrix-matrix product, the others column increments.
//
// Damping that couples the dynamic modes (discrete arm dampers: D_n = Phi_n^T C Phi_n not
// diagonal; no damping ratios given) would be lost by the per-mode recursion. The dynamic modes
// are then stepped together, exactly, by the discretised first-order form of
//   eta'' + D_n eta' + Omega_n^2 eta = p + p_g,   s = [eta; eta'],
//   s_{k+1} = Phi_d s_k + Gamma_0 p_k + Gamma_1 p_{k+1} + s_g        (discretization.h)
// O((2n)^2) per step instead of O(n), still with the input terms above (the tracked paper
// vehicle with two arm dampers, 71 modes below 500 Hz, long hill at 30 km/h: 19 ms). Across a
// quasi-static cut the dampers also couple the two groups; kept, as the mode-acceleration method
// keeps the quasi-static modes' statics:
//   the dampers' force on the dynamic modes from the quasi-static ones' rates,
//     p_n -= D_nt Omega_t^-2 Phi_t^T K_u u'        (a term of u' in G: exact in the recursion),
//   the quasi-static modes' static response to the dynamic modes' damping force,
//     eta_t -= Omega_t^-2 D_tn eta_n'              (outputs, state(), watched coordinates).
// Left out, as for the cut without dampers: their inertia, their own damping and the rates
// these terms would add to eta_t' (from eta_n'' and C_u u''). On a random model with dampers
// next to its tyres the cut then errs by what it costs without dampers (test_simulator: 4.6e-5,
// against 4 % with both terms dropped); on the paper vehicle the second is below 4e-8 of the
// dynamic modes' response (|d_sr| omega_r / omega_s^2). The neglected ratio reported is then 0.
class ModalEngine : public SimulatorEngine {
 public:
  ModalEngine(const SecondOrderSystem& system, const SimulatorOptions& options)
      : ModalEngine(system, ModalSystem(system, options.modal_damping_ratios), options) {}

  // `modal` is system's decomposition (its outputs may be other rows than system.output's).
  ModalEngine(const SecondOrderSystem& system, const ModalSystem& modal,
              const SimulatorOptions& options) {
    checkTruncation(options);
    const DofIndex n_all = modal.modeCount();
    const DofIndex n_u = system.inputCount();
    // Modes are in ascending frequency: the first n are dynamic, the rest quasi-static.
    DofIndex n = n_all;
    if (options.max_mode_frequency_hz > 0) {
      const double limit = 2.0 * kPi * options.max_mode_frequency_hz;
      n = 0;
      while (n < n_all && modal.naturalFrequencies()(n) <= limit)
        ++n;
    }
    const DofIndex n_t = n_all - n;
    const Vector omega = modal.naturalFrequencies().head(n);
    coefficients_ = discretizeModes(omega, modal.dampingCoefficients().head(n), options.time_step,
                                    options.hold);
    first_order_ = options.hold == InputHold::FirstOrder;
    omega_squared_ = omega.cwiseAbs2();
    damping_ = modal.dampingCoefficients().head(n);
    modal_output_ = modal.modalOutput().leftCols(n);
    shapes_ = modal.shapes().leftCols(n);
    mass_projection_ = modal.massProjection().topRows(n);
    const Vector modal_gravity =
        options.generalized_force.size() != 0
            ? Vector(modal.shapes().transpose() * options.generalized_force)
            : Vector(Vector::Zero(n_all));
    force_ = modal_gravity.head(n);
    const Vector gamma_disp = coefficients_.g0_disp + coefficients_.g1_disp;
    const Vector gamma_vel = coefficients_.g0_vel + coefficients_.g1_vel;
    offset_disp_ = gamma_disp.cwiseProduct(force_);
    offset_vel_ = gamma_vel.cwiseProduct(force_);
    double neglected = modal.maxOffDiagonalDampingRatio();
    if (options.modal_damping_ratios.size() == 0 && n > 1 &&
        neglected > kModalDampingCouplingTolerance) {
      const ModeShapes& phi = modal.shapes();
      const Matrix c_phi_n = system.damping * phi.leftCols(n);
      const Matrix d_n = phi.leftCols(n).transpose() * c_phi_n;
      if (maxOffDiagonalRatio(d_n) > kModalDampingCouplingTolerance) {
        coupleDynamicModes(omega, d_n, force_, options);
        cross_damping_ = phi.rightCols(n_all - n).transpose() * c_phi_n;  // D_tn
        neglected = 0.0;
      }
    }

    const OutputLayout layout(modal.outputNames(), options.quantities);
    n_y_ = modal.outputCount();
    disp_offset_ =
        layout.has(OutputQuantity::Displacement) ? layout.offset(OutputQuantity::Displacement) : -1;
    vel_offset_ =
        layout.has(OutputQuantity::Velocity) ? layout.offset(OutputQuantity::Velocity) : -1;
    acc_offset_ =
        layout.has(OutputQuantity::Acceleration) ? layout.offset(OutputQuantity::Acceleration) : -1;

    // G over all 2 n_u columns of w = [u; u'], rows [p (n); y_t (n_y, if displacements are
    // reported); y_t' (n_y, if velocities are)]. Quasi-static modes: eta_t = Omega_t^-2 Phi_t^T f,
    //   y_t  = H Phi_t Omega_t^-2 Phi_t^T (K_u u + C_u u') (+ r_g = H Phi_t Omega_t^-2 Phi_t^T
    //   f_g), y_t' = H Phi_t Omega_t^-2 Phi_t^T K_u u'   (the C_u u'' term is not available:
    //   dropped).
    const bool truncated = n_t > 0;
    disp_row_ = truncated && disp_offset_ >= 0 ? n : -1;
    vel_row_ = truncated && vel_offset_ >= 0 ? n + (disp_row_ >= 0 ? n_y_ : 0) : -1;
    const DofIndex g_rows = n + (disp_row_ >= 0 ? n_y_ : 0) + (vel_row_ >= 0 ? n_y_ : 0);
    Matrix psi_all(n_all, 2 * n_u);
    psi_all << modal.modalInputStiffness(), modal.modalInputDamping();
    Matrix g_all = Matrix::Zero(g_rows, 2 * n_u);
    g_all.topRows(n) = psi_all.topRows(n);
    residual_force_.setZero(n_y_);
    if (coupled_ && truncated) {
      // The dampers' force on the dynamic modes from the quasi-static ones' rates,
      // -D_nt eta_t' with eta_t' = Omega_t^-2 Phi_t^T K_u u' (C_u u'' unknown, as below): one
      // more linear term of u' in p.
      const Vector inverse_omega2 = modal.naturalFrequencies().tail(n_t).cwiseAbs2().cwiseInverse();
      g_all.block(0, n_u, n, n_u).noalias() -= cross_damping_.transpose() *
                                               inverse_omega2.asDiagonal() *
                                               modal.modalInputStiffness().bottomRows(n_t);
    }
    if (truncated) {
      const Vector inverse_omega2 = modal.naturalFrequencies().tail(n_t).cwiseAbs2().cwiseInverse();
      const Matrix output_flex =
          modal.modalOutput().rightCols(n_t) * inverse_omega2.asDiagonal();  // H Phi_t Omega^-2
      if (disp_row_ >= 0)
        g_all.middleRows(disp_row_, n_y_).noalias() = output_flex * psi_all.bottomRows(n_t);
      if (vel_row_ >= 0)
        g_all.block(vel_row_, n_u, n_y_, n_u).noalias() =
            output_flex * modal.modalInputStiffness().bottomRows(n_t);
      residual_force_.noalias() = output_flex * modal_gravity.tail(n_t);
      truncated_shapes_ = modal.shapes().rightCols(n_t) * inverse_omega2.asDiagonal();
      // Coupled dampers: the quasi-static modes' static response to the dynamic modes' damping
      // force, eta_t -= Omega_t^-2 D_tn eta_n', on the outputs (their rate, from eta_n'', is
      // left out like C_u u'').
      if (coupled_)
        residual_damping_.noalias() = output_flex * cross_damping_;
      truncated_psi_ = psi_all.bottomRows(n_t);
      truncated_gravity_ = modal_gravity.tail(n_t);
    }
    // Zero columns (e.g. C_u = 0: no ground damping) would only cost multiplications by zero.
    for (DofIndex j = 0; j < g_all.cols(); ++j)
      if (!g_all.col(j).isZero(0.0))
        active_inputs_.push_back(j);
    const auto m = static_cast<DofIndex>(active_inputs_.size());
    input_map_.resize(g_rows, m);
    for (DofIndex j = 0; j < m; ++j)
      input_map_.col(j) = g_all.col(active_inputs_[static_cast<std::size_t>(j)]);
    active_input_.setZero(m);
    input_terms_.setZero(g_rows);
    input_delta_.setZero(m);
    runs_.reserve(static_cast<std::size_t>(m));

    names_ = layout.names();
    off_diagonal_ratio_ = neglected;
    dt_ = options.time_step;
    hold_ = options.hold;
    method_ = DiscretizationMethod::ModalDecoupled;
    state_count_ = 2 * system.size();
    dynamic_modes_ = n;
    quasi_static_modes_ = n_t;
    n_u_ = n_u;

    for (Vector* v : {&eta_, &eta_dot_, &eta_next_, &eta_ddot_, &p_})
      v->setZero(n);
    w_.setZero(2 * n_u);
    y_.setZero(layout.size());
    updateOutputs();
  }

  void reset(const Vector& state, const Vector& input) override {
    const DofIndex n = shapes_.rows();
    eta_.noalias() = mass_projection_ * state.head(n);
    eta_dot_.noalias() = mass_projection_ * state.tail(n);
    steps_ = 0;
    setInput(input);
  }

  void setInput(const Vector& input) override {
    w_ = input;
    gatherActive(input);
    anchorInputTerms();
    p_ = input_terms_.head(p_.size());
    updateOutputs();
  }

  void advance(const Vector& input_next) override {
    updateInputTerms(input_next);
    advanceModes(p_.data(), input_terms_.data(), eta_.data(), eta_dot_.data(), eta_next_.data(),
                 eta_dot_.data());
    eta_.swap(eta_next_);
    p_ = input_terms_.head(p_.size());
    w_ = input_next;
    ++steps_;
    updateOutputs();
  }

  Vector state() const override {
    const DofIndex n = shapes_.rows();
    Vector z(2 * n);
    z.head(n).noalias() = shapes_ * eta_;
    z.tail(n).noalias() = shapes_ * eta_dot_;
    if (quasi_static_modes_ > 0) {
      // q_t = Phi_t Omega_t^-2 (Phi_t^T (K_u u + C_u u') + Phi_t^T f_g), q_t' from K_u u'.
      const Vector modal_force = truncated_psi_ * w_ + truncated_gravity_;
      z.head(n).noalias() += truncated_shapes_ * modal_force;
      if (cross_damping_.size() > 0)
        z.head(n).noalias() -= truncated_shapes_ * (cross_damping_ * eta_dot_);
      z.tail(n).noalias() += truncated_shapes_ * (truncated_psi_.leftCols(n_u_) * w_.tail(n_u_));
    }
    return z;
  }

  // The watched coordinates r of q, as state() computes them but with the products re-associated
  // so that each matrix is read once per call (no allocation):
  //   [q_r, q_r'] = Phi_r [eta, eta'] + F_r [u, u'] + [r_g + D_r u', 0],
  // F_r = (Phi_t Omega_t^-2)_r Phi_t^T K_u (n_r x n_u), D_r the same with C_u (kept only when
  // C_u is not zero), r_g = (Phi_t Omega_t^-2)_r Phi_t^T f_g. state() instead reads
  // Phi_t^T [K_u C_u] and Phi_t Omega_t^-2 whole, twice: ~6 MB on the tracked model against ~1 MB.
  void watchCoordinates(const std::vector<DofIndex>& rows) override {
    watch_rows_ = rows;
    const auto r = static_cast<DofIndex>(rows.size());
    const DofIndex n = shapes_.cols();
    watch_shapes_.resize(r, n);
    for (DofIndex i = 0; i < r; ++i)
      watch_shapes_.row(i) = shapes_.row(rows[static_cast<std::size_t>(i)]);
    watch_flex_.resize(0, 0);
    watch_damping_.resize(0, 0);
    watch_cross_.resize(0, 0);
    watch_gravity_.setZero(r);
    if (quasi_static_modes_ > 0) {
      Matrix truncated_rows(r, truncated_shapes_.cols());
      for (DofIndex i = 0; i < r; ++i)
        truncated_rows.row(i) = truncated_shapes_.row(rows[static_cast<std::size_t>(i)]);
      watch_flex_.noalias() = truncated_rows * truncated_psi_.leftCols(n_u_);
      Matrix damping = truncated_rows * truncated_psi_.rightCols(n_u_);
      if (!damping.isZero(0.0))
        watch_damping_ = std::move(damping);
      watch_gravity_.noalias() = truncated_rows * truncated_gravity_;
      if (cross_damping_.size() > 0)
        watch_cross_.noalias() = truncated_rows * cross_damping_;
    }
  }

  void coordinates(Vector* z) const override {
    const auto r = static_cast<DofIndex>(watch_rows_.size());
    if (z->size() != 2 * r)
      z->resize(2 * r);
    auto q = z->head(r);
    auto q_dot = z->tail(r);
    // Column by column, both results at once: each column of Phi_r and F_r is read once, and
    // no product packs its matrix (Eigen's GEMM copies the whole of F_r, 1 MB, every call).
    q.setZero();
    q_dot.setZero();
    for (DofIndex j = 0; j < watch_shapes_.cols(); ++j) {
      q.noalias() += eta_(j) * watch_shapes_.col(j);
      q_dot.noalias() += eta_dot_(j) * watch_shapes_.col(j);
    }
    if (watch_flex_.size() > 0) {
      for (DofIndex j = 0; j < n_u_; ++j) {
        q.noalias() += w_(j) * watch_flex_.col(j);
        q_dot.noalias() += w_(n_u_ + j) * watch_flex_.col(j);
      }
      q += watch_gravity_;
      if (watch_damping_.size() > 0)
        q.noalias() += watch_damping_ * w_.tail(n_u_);
      if (watch_cross_.size() > 0)
        q.noalias() -= watch_cross_ * eta_dot_;
    }
  }

  // Blocked version: the input terms g of kBlock samples at a time (by increments, or as one
  // matrix-matrix product when the inputs change densely), then the O(n) per-mode recursion, then
  // the outputs as matrix-matrix products (runBlocks).
  Matrix simulate(const Matrix& inputs) override {
    const DofIndex n_t = inputs.rows();
    const DofIndex m = input_map_.cols();
    Matrix outputs(n_t, y_.size());
    if (n_t == 0)
      return outputs;
    // A non-finite entry is refused before anything changes: the first (row, column) found. Row
    // 0 is checked here, the later rows of the columns the model uses where the scan below reads
    // them anyway (a sample equal to the one before is as finite). A column the model does not
    // use (all zeros in its input map: u' without ground damping) is not read at all: it cannot
    // reach the state, and a pass over it cost 5 ms of a 14 ms run.
    DofIndex bad_row = n_t, bad_column = 0;
    const auto flag = [&](DofIndex k, DofIndex column) {
      if (k < bad_row || (k == bad_row && column < bad_column)) {
        bad_row = k;
        bad_column = column;
      }
    };
    for (DofIndex c = 0; c < inputs.cols(); ++c)
      if (!std::isfinite(inputs(0, c)))
        flag(0, c);
    // The input changes of every block, found input by input in one streaming pass over the
    // column-major series (each input's samples are contiguous). A block where more than
    // 1/kDenseFraction of the inputs change, or one changes by a non-finite difference (non-finite
    // values are refused above; two finite ones can still differ by more than a double holds, and
    // an infinite delta must not leak into later samples through the sums), takes the dense
    // product instead.
    struct Change {
      DofIndex step;   // sample index in the series
      DofIndex input;  // column of input_map_
      double delta;
    };
    const DofIndex n_blocks = (n_t - 1 + kBlock - 1) / kBlock;
    std::vector<std::vector<Change>> changes(static_cast<std::size_t>(n_blocks));
    // dense: 1 = many changes, 2 = a non-finite change (then every column is multiplied).
    std::vector<char> dense(static_cast<std::size_t>(n_blocks), 0);
    // touched[block * m + j]: input j changes somewhere in the block.
    std::vector<char> touched(static_cast<std::size_t>(n_blocks * m), 0);
    // Runs of identical samples (flat terrain) are skipped a chunk at a time: bitwise-equal
    // samples are equal values (a NaN that stays NaN is NaN in the block's anchor anyway).
    constexpr DofIndex kChunk = 32;
    for (DofIndex j = 0; j < m; ++j) {
      const double* column = inputs.data() + active_inputs_[static_cast<std::size_t>(j)] * n_t;
      for (DofIndex k0 = 1; k0 < n_t; k0 += kChunk) {
        const DofIndex len = std::min(kChunk, n_t - k0);
        if (std::memcmp(column + k0, column + k0 - 1,
                        static_cast<std::size_t>(len) * sizeof(double)) == 0)
          continue;
        for (DofIndex k = k0; k < k0 + len; ++k) {
          const double delta = column[k] - column[k - 1];
          if (delta == 0.0)
            continue;
          if (!std::isfinite(column[k]))
            flag(k, active_inputs_[static_cast<std::size_t>(j)]);
          const auto block = static_cast<std::size_t>((k - 1) / kBlock);
          touched[block * static_cast<std::size_t>(m) + static_cast<std::size_t>(j)] = 1;
          if (!std::isfinite(delta))
            dense[block] = 2;
          if (dense[block])
            continue;
          const DofIndex b = std::min(kBlock, n_t - 1 - static_cast<DofIndex>(block) * kBlock);
          std::vector<Change>& list = changes[block];
          list.push_back({k, j, delta});
          if (static_cast<DofIndex>(list.size()) * kDenseFraction > m * b) {
            dense[block] = 1;
            std::vector<Change>().swap(list);
          }
        }
      }
    }
    if (bad_row < n_t)
      detail::throwNonFiniteSeriesEntry(bad_row, bad_column, inputs(bad_row, bad_column));
    setInput(inputs.row(0).transpose());
    outputs.row(0) = y_.transpose();
    std::vector<DofIndex> changing, rest, changing_inputs;
    runBlocks(n_t, outputs, [&](DofIndex k0, DofIndex b, Matrix& terms) {
      const auto block = static_cast<std::size_t>((k0 - 1) / kBlock);
      // g at sample k0 - 1 (exact), then g_k = g_{k-1} + G dw_k inside the block.
      gatherActive(inputs.row(k0 - 1));
      anchorInputTerms();
      if (dense[block]) {
        // The inputs that change in the block (columns `changing` of G) times their samples,
        // plus the constant part of the others: G(:, rest) w_{k0-1}(rest) for every sample.
        changing.clear();
        rest.clear();
        for (DofIndex j = 0; j < m; ++j) {
          const bool t = touched[block * static_cast<std::size_t>(m) + static_cast<std::size_t>(j)];
          (t ? changing : rest).push_back(j);
        }
        if (dense[block] == 2 || 4 * static_cast<DofIndex>(changing.size()) > 3 * m) {
          terms.leftCols(b).noalias() =
              input_map_ * inputs.middleRows(k0, b)(Eigen::all, active_inputs_).transpose();
        } else {
          changing_inputs.clear();
          for (const DofIndex j : changing)
            changing_inputs.push_back(active_inputs_[static_cast<std::size_t>(j)]);
          const Vector constant = input_map_(Eigen::all, rest) * active_input_(rest);
          terms.leftCols(b).noalias() =
              input_map_(Eigen::all, changing) *
              inputs.middleRows(k0, b)(Eigen::all, changing_inputs).transpose();
          terms.leftCols(b).colwise() += constant;
        }
        return;
      }
      terms.leftCols(b).setZero();
      for (const Change& c : changes[block])
        addInputColumn(input_map_.col(c.input).data(), c.delta, terms.col(c.step - k0).data());
      std::vector<Change>().swap(changes[block]);
      prefixSum(b, terms);
    });
    // Ends at the last sample with exact input terms.
    setInput(inputs.row(n_t - 1).transpose());
    return outputs;
  }

  // The held series (held_input_series.h): the changes are the channels' events, so nothing is
  // scanned, and a channel shared by several columns is one column of the channel map
  //   G_c(:, c) = sum over the active columns j of channel c of G(:, j),
  // so contacts that see the same profile cost one product.
  Matrix simulate(const HeldInputSeries& series) override {
    const DofIndex n_t = series.samples;
    const auto n_c = static_cast<DofIndex>(series.channels.size());
    Matrix outputs(n_t, y_.size());
    std::vector<DofIndex> active_index(static_cast<std::size_t>(series.inputCount()), -1);
    for (std::size_t a = 0; a < active_inputs_.size(); ++a)
      active_index[static_cast<std::size_t>(active_inputs_[a])] = static_cast<DofIndex>(a);
    Matrix channel_map = Matrix::Zero(input_map_.rows(), n_c);
    std::vector<double> value(static_cast<std::size_t>(n_c));
    std::vector<std::size_t> next(static_cast<std::size_t>(n_c), 0);
    std::vector<char> drives(static_cast<std::size_t>(n_c), 0);  // a non-zero column of the map
    for (DofIndex c = 0; c < n_c; ++c) {
      const HeldInputSeries::Channel& ch = series.channels[static_cast<std::size_t>(c)];
      for (const DofIndex j : ch.columns)
        if (active_index[static_cast<std::size_t>(j)] >= 0)
          channel_map.col(c) += input_map_.col(active_index[static_cast<std::size_t>(j)]);
      value[static_cast<std::size_t>(c)] =
          ch.columns.empty() ? 0.0 : series.initial(ch.columns.front());
      drives[static_cast<std::size_t>(c)] = !channel_map.col(c).isZero(0.0);
    }
    Vector w = series.initial;
    setInput(w);
    outputs.row(0) = y_.transpose();
    // deltas(s, j): change of the s-th touched channel of the block at its sample j (rows are
    // zeroed when a channel is touched; only the first n_touched rows are in use).
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> deltas(n_c, kBlock);
    Matrix map_touched;
    std::vector<DofIndex> touched;
    runBlocks(n_t, outputs, [&](DofIndex k0, DofIndex b, Matrix& terms) {
      gatherActive(w);
      anchorInputTerms();
      // This block's events; w advances to the block's last sample.
      touched.clear();
      long events = 0;
      for (DofIndex c = 0; c < n_c; ++c) {
        const HeldInputSeries::Channel& ch = series.channels[static_cast<std::size_t>(c)];
        std::size_t& e = next[static_cast<std::size_t>(c)];
        if (e == ch.steps.size() || ch.steps[e] >= k0 + b)
          continue;
        double& v = value[static_cast<std::size_t>(c)];
        const bool drives_c = drives[static_cast<std::size_t>(c)];
        const auto slot = static_cast<DofIndex>(touched.size());
        if (drives_c) {
          touched.push_back(c);
          deltas.row(slot).head(b).setZero();
        }
        for (; e < ch.steps.size() && ch.steps[e] < k0 + b; ++e) {
          if (drives_c)
            deltas(slot, static_cast<DofIndex>(ch.steps[e] - k0)) = ch.values[e] - v;
          v = ch.values[e];
          ++events;
        }
        for (const DofIndex j : ch.columns)
          w(j) = v;
      }
      const auto n_touched = static_cast<DofIndex>(touched.size());
      if (events * kDenseFraction > n_touched * b) {
        // Dense: one product of the touched channels' columns with their changes.
        map_touched = channel_map(Eigen::all, touched);
        terms.leftCols(b).noalias() = map_touched * deltas.topLeftCorner(n_touched, b);
        prefixSum(b, terms);
        return;
      }
      // Few changes (none on flat terrain): g_k = g_{k-1} plus the changes at k, in one pass.
      for (DofIndex j = 0; j < b; ++j) {
        if (j == 0)
          terms.col(0) = input_terms_;
        else
          terms.col(j) = terms.col(j - 1);
        for (DofIndex slot = 0; slot < n_touched; ++slot)
          if (deltas(slot, j) != 0.0)
            addInputColumn(channel_map.col(touched[static_cast<std::size_t>(slot)]).data(),
                           deltas(slot, j), terms.col(j).data());
      }
    });
    setInput(w);
    return outputs;
  }

 private:
  using ArrayMap = Eigen::Map<Eigen::ArrayXd>;
  using ConstArrayMap = Eigen::Map<const Eigen::ArrayXd>;
  /// Increments give way to a full product after this many steps (bounds rounding drift) ...
  static constexpr long kAnchorSteps = 1000;
  /// simulate(): a block of samples with more than 1 / kDenseFraction of the inputs changing
  /// per sample takes the matrix-matrix product (blocked, it is then the faster one).
  static constexpr DofIndex kDenseFraction = 8;
  /// step(): changed columns at most this many unchanged columns apart share one product (a
  /// zero column costs less than the call of another product).
  static constexpr DofIndex kRunGap = 4;

  // active_input_ = the active columns of w (any vector or row expression of w).
  template <typename Row>
  void gatherActive(const Row& input) {
    for (std::size_t j = 0; j < active_inputs_.size(); ++j)
      active_input_(static_cast<DofIndex>(j)) = input(active_inputs_[j]);
  }

  /// Samples per block of simulate().
  static constexpr DofIndex kBlock = 256;

  // terms += g delta, g a column of input_map_'s height.
  void addInputColumn(const double* g, double delta, double* terms) const {
    for (DofIndex i = 0; i < input_map_.rows(); ++i)
      terms[i] += g[i] * delta;
  }

  // terms(:, 0..b-1) hold the increments G dw_k of the block: turned into g_k from the anchor
  // input_terms_ = g_{k0-1}.
  void prefixSum(DofIndex b, Matrix& terms) const {
    terms.col(0) += input_terms_;
    for (DofIndex k = 1; k < b; ++k)
      terms.col(k) += terms.col(k - 1);
  }

  // The simulate() loop after sample 0 (set, with outputs.row(0)): blocks of kBlock samples.
  // fill(k0, b, terms) anchors input_terms_ at sample k0 - 1 and writes g_k for samples
  // k0 .. k0 + b - 1 into terms' first b columns; then the modes advance through the block and
  // the outputs of the block are matrix products.
  template <typename Fill>
  void runBlocks(DofIndex n_t, Matrix& outputs, Fill&& fill) {
    const DofIndex n = eta_.size();
    Matrix terms(input_map_.rows(), kBlock), disp(n, kBlock), vel(n, kBlock), acc(n, kBlock);
    for (DofIndex k0 = 1; k0 < n_t; k0 += kBlock) {
      const DofIndex b = std::min(kBlock, n_t - k0);
      fill(k0, b, terms);
      p_ = input_terms_.head(n);
      for (DofIndex j = 0; j < b; ++j) {
        const double* p_prev = j == 0 ? p_.data() : terms.col(j - 1).data();
        const double* eta_prev = j == 0 ? eta_.data() : disp.col(j - 1).data();
        const double* eta_dot_prev = j == 0 ? eta_dot_.data() : vel.col(j - 1).data();
        advanceModes(p_prev, terms.col(j).data(), eta_prev, eta_dot_prev, disp.col(j).data(),
                     vel.col(j).data());
      }
      if (acc_offset_ >= 0) {
        acc.leftCols(b) = (terms.topLeftCorner(n, b).colwise() + force_).array() -
                          disp.leftCols(b).array().colwise() * omega_squared_.array() -
                          vel.leftCols(b).array().colwise() * damping_.array();
        if (coupled_)
          acc.leftCols(b).noalias() -= coupled_damping_ * vel.leftCols(b);
      }
      auto rows = outputs.middleRows(k0, b);
      if (disp_offset_ >= 0) {
        rows.middleCols(disp_offset_, n_y_).noalias() =
            disp.leftCols(b).transpose() * modal_output_.transpose();
        if (disp_row_ >= 0) {
          rows.middleCols(disp_offset_, n_y_) += terms.block(disp_row_, 0, n_y_, b).transpose();
          rows.middleCols(disp_offset_, n_y_).rowwise() += residual_force_.transpose();
          if (residual_damping_.size() > 0)
            rows.middleCols(disp_offset_, n_y_).noalias() -=
                vel.leftCols(b).transpose() * residual_damping_.transpose();
        }
      }
      if (vel_offset_ >= 0) {
        rows.middleCols(vel_offset_, n_y_).noalias() =
            vel.leftCols(b).transpose() * modal_output_.transpose();
        if (vel_row_ >= 0)
          rows.middleCols(vel_offset_, n_y_) += terms.block(vel_row_, 0, n_y_, b).transpose();
      }
      if (acc_offset_ >= 0)
        rows.middleCols(acc_offset_, n_y_).noalias() =
            acc.leftCols(b).transpose() * modal_output_.transpose();
      eta_ = disp.col(b - 1);
      eta_dot_ = vel.col(b - 1);
      steps_ += b;
    }
  }

  void anchorInputTerms() {
    input_terms_.noalias() = input_map_ * active_input_;
    steps_since_anchor_ = 0;
  }

  // input_terms_ = G w_next and active_input_ = the active part of w_next (class comment).
  void updateInputTerms(const Vector& input_next) {
    runs_.clear();
    bool finite = true;
    const auto m = static_cast<DofIndex>(active_inputs_.size());
    for (DofIndex j = 0; j < m; ++j) {
      const double value = input_next(active_inputs_[static_cast<std::size_t>(j)]);
      const double delta = value - active_input_(j);
      if (delta != 0.0) {
        input_delta_(j) = delta;
        active_input_(j) = value;
        finite = finite && std::isfinite(delta);
        if (!runs_.empty() && j - runs_.back().second <= kRunGap + 1)
          runs_.back().second = j;
        else
          runs_.emplace_back(j, j);
      }
    }
    DofIndex width = 0;
    for (const auto& [a, b] : runs_)
      width += b - a + 1;
    // A non-finite input (or one just replaced) must not stay in the sums: full product. So
    // also when the runs cover most columns: it costs hardly more, and re-anchors.
    if (++steps_since_anchor_ >= kAnchorSteps || !finite || 4 * width > 3 * m) {
      anchorInputTerms();
    } else {
      for (const auto& [a, b] : runs_) {
        if (a == b)
          input_terms_ += input_delta_(a) * input_map_.col(a);
        else
          input_terms_.noalias() +=
              input_map_.middleCols(a, b - a + 1) * input_delta_.segment(a, b - a + 1);
      }
    }
    for (const auto& [a, b] : runs_)
      input_delta_.segment(a, b - a + 1).setZero();
  }

  // One step of every mode; eta_dot_out may alias eta_dot (coefficient-wise).
  void advanceModes(const double* p, const double* p_next, const double* eta, const double* eta_dot,
                    double* eta_out, double* eta_dot_out) const {
    const DofIndex n = eta_.size();
    if (coupled_) {
      // s_{k+1} = Phi_d s_k + Gamma_0 p_k (+ Gamma_1 p_{k+1}) + s_g, into the scratch first:
      // eta_dot_out may be eta_dot.
      const Eigen::Map<const Vector> x(eta, n), v(eta_dot, n), p0(p, n), p1(p_next, n);
      Vector& next = coupled_next_;
      next = coupled_offset_;
      next.noalias() += coupled_transition_.leftCols(n) * x;
      next.noalias() += coupled_transition_.rightCols(n) * v;
      next.noalias() += coupled_input_ * p0;
      if (first_order_)
        next.noalias() += coupled_next_input_ * p1;
      Eigen::Map<Vector>(eta_out, n) = next.head(n);
      Eigen::Map<Vector>(eta_dot_out, n) = next.tail(n);
      return;
    }
    const ConstArrayMap p0(p, n), p1(p_next, n), x(eta, n), v(eta_dot, n);
    const DiscreteModes& c = coefficients_;
    ArrayMap x_out(eta_out, n), v_out(eta_dot_out, n);
    if (first_order_) {
      x_out = c.a11.array() * x + c.a12.array() * v + c.g0_disp.array() * p0 +
              c.g1_disp.array() * p1 + offset_disp_.array();
      v_out = c.a21.array() * x + c.a22.array() * v + c.g0_vel.array() * p0 +
              c.g1_vel.array() * p1 + offset_vel_.array();
    } else {
      x_out = c.a11.array() * x + c.a12.array() * v + c.g0_disp.array() * p0 + offset_disp_.array();
      v_out = c.a21.array() * x + c.a22.array() * v + c.g0_vel.array() * p0 + offset_vel_.array();
    }
  }

  // input_terms_ holds G w for the current w.
  void updateOutputs() {
    if (disp_offset_ >= 0) {
      y_.segment(disp_offset_, n_y_).noalias() = modal_output_ * eta_;
      if (disp_row_ >= 0) {
        y_.segment(disp_offset_, n_y_) += input_terms_.segment(disp_row_, n_y_) + residual_force_;
        if (residual_damping_.size() > 0)
          y_.segment(disp_offset_, n_y_).noalias() -= residual_damping_ * eta_dot_;
      }
    }
    if (vel_offset_ >= 0) {
      y_.segment(vel_offset_, n_y_).noalias() = modal_output_ * eta_dot_;
      if (vel_row_ >= 0)
        y_.segment(vel_offset_, n_y_) += input_terms_.segment(vel_row_, n_y_);
    }
    if (acc_offset_ >= 0) {
      eta_ddot_.array() = p_.array() + force_.array() - omega_squared_.array() * eta_.array() -
                          damping_.array() * eta_dot_.array();
      if (coupled_)
        eta_ddot_.noalias() -= coupled_damping_ * eta_dot_;
      y_.segment(acc_offset_, n_y_).noalias() = modal_output_ * eta_ddot_;
    }
  }

  // The dynamic modes stepped together (class comment): [eta; eta'] of
  // eta'' + D_n eta' + Omega_n^2 eta = p + p_g discretised with the run's hold; damping_ is then
  // zero and coupled_damping_ is D_n whole (for eta'').
  void coupleDynamicModes(const Vector& omega, const Matrix& d_n, const Vector& modal_gravity,
                          const SimulatorOptions& options) {
    const DofIndex n = omega.size();
    StateSpace c;
    c.state_matrix = Matrix::Zero(2 * n, 2 * n);
    c.state_matrix.topRightCorner(n, n).setIdentity();
    c.state_matrix.bottomLeftCorner(n, n) = -Matrix(omega.cwiseAbs2().asDiagonal());
    c.state_matrix.bottomRightCorner(n, n) = -d_n;
    c.input_matrix = Matrix::Zero(2 * n, n);
    c.input_matrix.bottomRows(n).setIdentity();
    c.output_matrix = Matrix::Zero(0, 2 * n);
    c.feedthrough_matrix = Matrix::Zero(0, n);
    c.state_offset = Vector::Zero(2 * n);
    c.state_offset.tail(n) = modal_gravity;
    const StateSpace discrete = discretize(c, options.time_step, options.hold);
    coupled_ = true;
    coupled_transition_ = discrete.state_matrix;
    coupled_input_ = discrete.input_matrix;
    coupled_next_input_ = discrete.next_input_matrix;
    coupled_offset_ = discrete.state_offset.size() ? discrete.state_offset : Vector::Zero(2 * n);
    coupled_damping_ = d_n;
    damping_.setZero(n);
    coupled_next_.setZero(2 * n);
  }

  DiscreteModes coefficients_;
  bool first_order_ = false;
  bool coupled_ = false;
  Matrix coupled_transition_, coupled_input_, coupled_next_input_, coupled_damping_;
  // D_tn (quasi-static x dynamic) and H Phi_t Omega_t^-2 D_tn; empty unless coupled and cut.
  Matrix cross_damping_, residual_damping_;
  Vector coupled_offset_;
  mutable Vector coupled_next_;
  Matrix modal_output_, shapes_, mass_projection_;
  Vector omega_squared_, damping_, force_, offset_disp_, offset_vel_;
  Vector eta_, eta_dot_, eta_next_, eta_ddot_, p_;
  // Input terms g = G w (class comment): G = input_map_ on the active columns of w.
  std::vector<DofIndex> active_inputs_;  // columns of w with a non-zero column of G
  Vector active_input_;                  // w restricted to active_inputs_
  Matrix input_map_;
  Vector input_terms_;
  DofIndex disp_row_ = -1, vel_row_ = -1;  // rows of y_t, y_t' in g (-1: none)
  Vector input_delta_;  // w_{k+1} - w_k on the active columns, zero outside runs_
  std::vector<std::pair<DofIndex, DofIndex>> runs_;  // changed columns a..b of the last step
  long steps_since_anchor_ = 0;
  DofIndex n_y_ = 0;
  DofIndex disp_offset_ = -1, vel_offset_ = -1, acc_offset_ = -1;
  // Quasi-static (truncated) modes, see the constructor.
  DofIndex n_u_ = 0;
  Matrix truncated_shapes_, truncated_psi_;
  Vector residual_force_, truncated_gravity_;
  // watchCoordinates(): Phi_r, F_r, D_r (empty when C_u = 0), r_g, and the rows of
  // Phi_t Omega_t^-2 D_tn (coupled dampers with quasi-static modes; else empty).
  Matrix watch_shapes_, watch_flex_, watch_damping_, watch_cross_;
  Vector watch_gravity_;
};

}  // namespace

std::unique_ptr<SimulatorEngine> makeModalEngine(const SecondOrderSystem& system,
                                                 const SimulatorOptions& options) {
  return std::make_unique<ModalEngine>(system, options);
}

std::unique_ptr<SimulatorEngine> makeModalEngine(const SecondOrderSystem& system,
                                                 const ModalSystem& modal,
                                                 const SimulatorOptions& options) {
  return std::make_unique<ModalEngine>(system, modal, options);
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
