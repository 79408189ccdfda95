// The dense engine: steps a discretised StateSpace (simulator_engine.h).
#include <memory>
#include <string>

#include "simulator_engine.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace {

// z_{k+1} = Phi z_k + Gamma0 w_k (+ Gamma1 w_{k+1}) + f_d;  y = C z + D w + y0.
class DenseEngine : public SimulatorEngine {
 public:
  explicit DenseEngine(const StateSpace& d) {
    phi_ = d.state_matrix;
    gamma0_ = d.input_matrix;
    first_order_ = d.next_input_matrix.size() != 0;
    if (first_order_)
      gamma1_ = d.next_input_matrix;
    c_ = d.output_matrix;
    d_ = d.feedthrough_matrix;
    f_ = d.state_offset.size() != 0 ? d.state_offset : Vector::Zero(d.stateCount());
    y0_ = d.output_offset.size() != 0 ? d.output_offset : Vector::Zero(d.outputCount());
    has_offset_ = !f_.isZero(0.0);
    z_.setZero(d.stateCount());
    z_next_.setZero(d.stateCount());
    w_.setZero(d.inputCount());
    y_.setZero(d.outputCount());
    dt_ = d.sample_time;
    hold_ = d.hold;
    state_count_ = d.stateCount();
    names_ = d.output_names;
    if (names_.empty())
      for (DofIndex i = 0; i < d.outputCount(); ++i)
        names_.push_back("output " + std::to_string(i));
    updateOutputs();
  }

  void reset(const Vector& state, const Vector& input) override {
    z_ = state;
    w_ = input;
    steps_ = 0;
    updateOutputs();
  }

  void setInput(const Vector& input) override {
    w_ = input;
    updateOutputs();
  }

  void advance(const Vector& input_next) override {
    z_next_.noalias() = phi_ * z_;
    z_next_.noalias() += gamma0_ * w_;
    if (first_order_)
      z_next_.noalias() += gamma1_ * input_next;
    if (has_offset_)
      z_next_ += f_;
    z_.swap(z_next_);
    w_ = input_next;
    ++steps_;
    updateOutputs();
  }

  Vector state() const override { return z_; }

 private:
  void updateOutputs() {
    y_.noalias() = c_ * z_;
    y_.noalias() += d_ * w_;
    y_ += y0_;
  }

  Matrix phi_, gamma0_, gamma1_, c_, d_;
  Vector f_, y0_, z_, z_next_;
  bool first_order_ = false;
  bool has_offset_ = false;
};

}  // namespace

std::unique_ptr<SimulatorEngine> makeDenseEngine(const StateSpace& discrete) {
  return std::make_unique<DenseEngine>(discrete);
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
