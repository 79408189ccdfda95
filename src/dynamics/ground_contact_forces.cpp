#include "tracked_vehicle_dynamics/dynamics/ground_contact_forces.h"

#include <algorithm>
#include <string>
#include <utility>

#include "checks.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

bool anyDamped(const std::vector<GroundContact>& contacts) {
  for (const GroundContact& c : contacts)
    if (c.damping != 0.0)
      return true;
  return false;
}

// The run's system with H = the contacts' coordinates, one row per contact.
SecondOrderSystem coordinateSystem(const SecondOrderSystem& system,
                                   const std::vector<GroundContact>& contacts) {
  if (contacts.empty())
    throw InputError("ground contact forces: no contacts");
  SecondOrderSystem s = system;
  const auto n_c = static_cast<DofIndex>(contacts.size());
  s.output = Matrix::Zero(n_c, system.size());
  s.output_names.clear();
  for (DofIndex i = 0; i < n_c; ++i) {
    const GroundContact& c = contacts[static_cast<std::size_t>(i)];
    if (c.coordinate < 0 || c.coordinate >= system.size() || c.input < 0 ||
        c.input >= system.inputCount())
      throw InputError("ground contact forces: contact " + std::to_string(i) + " (input " +
                       std::to_string(c.input) + ", coordinate " + std::to_string(c.coordinate) +
                       ") is outside the system (" + std::to_string(system.inputCount()) +
                       " inputs, " + std::to_string(system.size()) + " coordinates)");
    s.output(i, c.coordinate) = 1.0;
    s.output_names.push_back("contact " + std::to_string(i));
  }
  return s;
}

SimulatorOptions coordinateOptions(SimulatorOptions options, bool damped) {
  options.quantities = {OutputQuantity::Displacement};
  if (damped)
    options.quantities.push_back(OutputQuantity::Velocity);
  return options;
}

// The contacts' Simulator: on the run's modes when they are given (H Phi with H = the contacts'
// coordinates), else from its own decomposition.
Simulator coordinateSimulator(const SecondOrderSystem& system,
                              const std::vector<GroundContact>& contacts, SimulatorOptions options,
                              const ModalSystem* modal) {
  const SecondOrderSystem s = coordinateSystem(system, contacts);
  const SimulatorOptions o = coordinateOptions(std::move(options), anyDamped(contacts));
  if (!modal)
    return Simulator(s, o);
  return Simulator(s, modal->withOutput(s.output, s.output_names), o);
}

// The contacts' Simulator on the run's discretisation: its Phi and Gamma, the contacts' output
// equation (discretize() keeps the continuous state, so C, D and y0 carry over as they are).
Simulator coordinateSimulator(const SecondOrderSystem& system,
                              const std::vector<GroundContact>& contacts, SimulatorOptions options,
                              const StateSpace& discrete) {
  const SecondOrderSystem s = coordinateSystem(system, contacts);
  const SimulatorOptions o = coordinateOptions(std::move(options), anyDamped(contacts));
  if (o.method != DiscretizationMethod::AugmentedExponential)
    throw InputError(
        "ground contact forces: a shared discretisation needs the augmented "
        "exponential method");
  const StateSpace outputs = fromSecondOrder(s, o.quantities, o.generalized_force);
  if (discrete.isContinuous() || discrete.stateCount() != outputs.stateCount() ||
      discrete.inputCount() != outputs.inputCount())
    throw InputError("ground contact forces: the shared discretisation has " +
                     std::to_string(discrete.stateCount()) + " states and " +
                     std::to_string(discrete.inputCount()) + " inputs (sample time " +
                     brief(discrete.sample_time) + " s), the system " +
                     std::to_string(outputs.stateCount()) + " and " +
                     std::to_string(outputs.inputCount()));
  StateSpace d = discrete;
  d.output_matrix = outputs.output_matrix;
  d.feedthrough_matrix = outputs.feedthrough_matrix;
  d.output_offset = outputs.output_offset;
  d.output_names = outputs.output_names;
  return Simulator(d);
}

// out[k] = w_k(column) for k = 0 .. samples-1 from the held series (its channel's events).
void heldColumn(const HeldInputSeries& series, const std::vector<DofIndex>& channel_of,
                DofIndex column, double* out) {
  double value = series.initial(column);
  const DofIndex c = channel_of[static_cast<std::size_t>(column)];
  long k = 0;
  if (c >= 0) {
    const HeldInputSeries::Channel& ch = series.channels[static_cast<std::size_t>(c)];
    for (std::size_t e = 0; e < ch.steps.size(); ++e) {
      for (; k < ch.steps[e]; ++k)
        out[k] = value;
      value = ch.values[e];
    }
  }
  for (; k < series.samples; ++k)
    out[k] = value;
}

// Cuts a held series into consecutive slices [first, first + count) in one pass over its events
// (a cursor per channel): slice() returns the series of those samples, its initial row the
// input at `first`; slices must be asked for in order, each starting at or after the previous
// one's first sample.
class HeldSlicer {
 public:
  explicit HeldSlicer(const HeldInputSeries& series)
      : series_(series), w_(series.initial), next_(series.channels.size(), 0) {}

  HeldInputSeries slice(long first, long count) {
    // Bring w_ to sample `first`.
    for (std::size_t c = 0; c < series_.channels.size(); ++c) {
      const HeldInputSeries::Channel& ch = series_.channels[c];
      std::size_t& e = next_[c];
      for (; e < ch.steps.size() && ch.steps[e] <= first; ++e)
        for (const DofIndex j : ch.columns)
          w_(j) = ch.values[e];
    }
    HeldInputSeries out;
    out.samples = count;
    out.initial = w_;
    for (std::size_t c = 0; c < series_.channels.size(); ++c) {
      const HeldInputSeries::Channel& ch = series_.channels[c];
      std::size_t e = next_[c];
      if (e == ch.steps.size() || ch.steps[e] >= first + count)
        continue;
      HeldInputSeries::Channel part;
      part.columns = ch.columns;
      for (; e < ch.steps.size() && ch.steps[e] < first + count; ++e) {
        part.steps.push_back(ch.steps[e] - first);
        part.values.push_back(ch.values[e]);
      }
      out.channels.push_back(std::move(part));
    }
    return out;
  }

 private:
  const HeldInputSeries& series_;
  Vector w_;
  std::vector<std::size_t> next_;
};

// The chunks of a series of `samples` rows: the first starts at row 0, each next one at the last
// row of the previous (Simulator::simulate's row 0 is the current input), so calls
// run(first, count, skip) with `skip` rows (0 or 1) already handed on.
template <typename Run>
void forEachChunk(long samples, long chunk, Run&& run) {
  for (long first = 0; first == 0 || first < samples - 1; first += chunk) {
    const long count = std::min(first + chunk + 1, samples) - first;
    run(first, count, first == 0 ? 0 : 1);
  }
}

}  // namespace

GroundContactForces::GroundContactForces(const SecondOrderSystem& system,
                                         std::vector<GroundContact> contacts,
                                         SimulatorOptions options, const ModalSystem* modal)
    : contacts_(std::move(contacts)),
      sim_(coordinateSimulator(system, contacts_, std::move(options), modal)),
      n_u_(system.inputCount()),
      damped_(anyDamped(contacts_)) {}

GroundContactForces::GroundContactForces(const SecondOrderSystem& system,
                                         std::vector<GroundContact> contacts,
                                         SimulatorOptions options, const StateSpace& discrete)
    : contacts_(std::move(contacts)),
      sim_(coordinateSimulator(system, contacts_, std::move(options), discrete)),
      n_u_(system.inputCount()),
      damped_(anyDamped(contacts_)) {}

void GroundContactForces::reset(const Vector& state, const Vector& input) {
  sim_.reset(state, input);
}

void GroundContactForces::subtractCoordinates(const Matrix& coordinates, Matrix& forces) const {
  const DofIndex n_c = contactCount();
  for (DofIndex i = 0; i < n_c; ++i) {
    const GroundContact& c = contacts_[static_cast<std::size_t>(i)];
    forces.col(i) = c.stiffness * (forces.col(i) - coordinates.col(i));
    if (damped_)
      forces.col(i) += c.damping * (forces.col(n_c + i) - coordinates.col(n_c + i));
  }
}

void GroundContactForces::simulate(const Matrix& inputs, const Sink& sink) {
  if (inputs.cols() != sim_.inputCount())
    throw InputError("GroundContactForces::simulate: the input series has " +
                     std::to_string(inputs.cols()) + " columns, the system " +
                     std::to_string(sim_.inputCount()));
  const DofIndex n_c = contactCount();
  forEachChunk(inputs.rows(), kChunk, [&](long first, long count, long skip) {
    const Matrix q = sim_.simulate(Matrix(inputs.middleRows(first, count)));
    forces_.resize(count, damped_ ? 2 * n_c : n_c);
    for (DofIndex i = 0; i < n_c; ++i) {
      const DofIndex j = contacts_[static_cast<std::size_t>(i)].input;
      forces_.col(i) = inputs.col(j).segment(first, count);
      if (damped_)
        forces_.col(n_c + i) = inputs.col(n_u_ + j).segment(first, count);
    }
    subtractCoordinates(q, forces_);
    sink(first + skip, forces_.block(skip, 0, count - skip, n_c));
  });
}

void GroundContactForces::simulate(const HeldInputSeries& inputs, const Sink& sink) {
  if (inputs.inputCount() != sim_.inputCount())
    throw InputError("GroundContactForces::simulate: the held input series has " +
                     std::to_string(inputs.inputCount()) + " inputs, the system " +
                     std::to_string(sim_.inputCount()));
  inputs.validate();
  const DofIndex n_c = contactCount();
  HeldSlicer slicer(inputs);
  std::vector<DofIndex> channel_of;
  forEachChunk(inputs.samples, kChunk, [&](long first, long count, long skip) {
    const HeldInputSeries part = slicer.slice(first, count);
    const Matrix q = sim_.simulate(part);
    channel_of.assign(static_cast<std::size_t>(part.inputCount()), -1);
    for (std::size_t c = 0; c < part.channels.size(); ++c)
      for (const DofIndex j : part.channels[c].columns)
        channel_of[static_cast<std::size_t>(j)] = static_cast<DofIndex>(c);
    forces_.resize(count, damped_ ? 2 * n_c : n_c);
    for (DofIndex i = 0; i < n_c; ++i) {
      const DofIndex j = contacts_[static_cast<std::size_t>(i)].input;
      heldColumn(part, channel_of, j, forces_.col(i).data());
      if (damped_)
        heldColumn(part, channel_of, n_u_ + j, forces_.col(n_c + i).data());
    }
    subtractCoordinates(q, forces_);
    sink(first + skip, forces_.block(skip, 0, count - skip, n_c));
  });
}

Matrix GroundContactForces::simulate(const Matrix& inputs) {
  Matrix all(inputs.rows(), contactCount());
  simulate(inputs, [&](long first, const Eigen::Ref<const Matrix>& f) {
    all.middleRows(first, f.rows()) = f;
  });
  return all;
}

Matrix GroundContactForces::simulate(const HeldInputSeries& inputs) {
  Matrix all(inputs.samples, contactCount());
  simulate(inputs, [&](long first, const Eigen::Ref<const Matrix>& f) {
    all.middleRows(first, f.rows()) = f;
  });
  return all;
}

Vector GroundContactForces::forces(const Vector& state, const Vector& input) const {
  const DofIndex n = sim_.stateCount() / 2;
  detail::requireLength("GroundContactForces::forces", "state z", state, 2 * n);
  detail::requireLength("GroundContactForces::forces", "input w", input, 2 * n_u_);
  Vector f(contactCount());
  contactForces(contacts_, state, input, n_u_, f, "GroundContactForces::forces");
  return f;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
