#include "tracked_vehicle_dynamics/fem/system.h"

#include <algorithm>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/beam_element.h"
#include "tracked_vehicle_dynamics/fem/geometric_stiffness.h"
#include "tracked_vehicle_dynamics/fem/mass_element.h"
#include "tracked_vehicle_dynamics/fem/spring_element.h"

namespace tracked_vehicle_dynamics {
namespace fem {

namespace {

// Element matrices scattered onto physical DOFs, before the constraint transformation.
struct PhysicalMatrices {
  std::vector<Triplet> k, m, c, ku, cu;
  std::vector<DofRef> ground_inputs;
};

template <int N>
void scatter(std::vector<Triplet>& out, const Eigen::Matrix<double, N, N>& e,
             const DofIndex (&dofs)[N / kDofsPerNode]) {
  for (int a = 0; a < N / kDofsPerNode; ++a)
    for (int b = 0; b < N / kDofsPerNode; ++b)
      for (int i = 0; i < kDofsPerNode; ++i)
        for (int j = 0; j < kDofsPerNode; ++j) {
          const double v = e(a * kDofsPerNode + i, b * kDofsPerNode + j);
          if (v != 0.0)
            out.emplace_back(dofs[a] + i, dofs[b] + j, v);
        }
}

PhysicalMatrices elementMatrices(const Model& model,
                                 const std::unordered_map<NodeId, std::size_t>& index) {
  PhysicalMatrices pm;
  auto base = [&](NodeId id) { return static_cast<DofIndex>(index.at(id)) * kDofsPerNode; };
  auto pos = [&](NodeId id) -> const Vector3& { return model.nodes[index.at(id)].position; };

  for (std::size_t i = 0; i < model.beams.size(); ++i) {
    const Beam& beam = model.beams[i];
    try {
      const BeamMatrices e =
          beamMatrices(pos(beam.n1), pos(beam.n2), beam.orientation,
                       *model.findMaterial(beam.material), *model.findSection(beam.section));
      const DofIndex dofs[2] = {base(beam.n1), base(beam.n2)};
      scatter<12>(pm.k, e.stiffness, dofs);
      scatter<12>(pm.m, e.mass, dofs);
      if (beam.axial_force != 0.0)
        scatter<12>(pm.k,
                    beamGeometricStiffness(pos(beam.n1), pos(beam.n2), beam.orientation,
                                           *model.findSection(beam.section), beam.axial_force),
                    dofs);
    } catch (const InputError& err) {
      throw InputError("beams[" + std::to_string(i) + "]: " + err.what());
    }
  }
  for (const Spring& spring : model.springs) {
    if (spring.n2 == kGround) {
      const GroundSpringMatrices e = groundSpringMatrices(spring, pos(spring.n1));
      const DofIndex dofs[1] = {base(spring.n1)};
      scatter<6>(pm.k, e.stiffness, dofs);
      scatter<6>(pm.c, e.damping, dofs);
      const auto column = static_cast<DofIndex>(pm.ground_inputs.size());
      for (int i = 0; i < kDofsPerNode; ++i) {
        if (e.input_stiffness(i) != 0.0)
          pm.ku.emplace_back(dofs[0] + i, column, e.input_stiffness(i));
        if (e.input_damping(i) != 0.0)
          pm.cu.emplace_back(dofs[0] + i, column, e.input_damping(i));
      }
      pm.ground_inputs.push_back(DofRef{spring.n1, static_cast<int>(Direction::Uz)});
    } else {
      const SpringMatrices e = springMatrices(spring, pos(spring.n1), pos(spring.n2));
      const DofIndex dofs[2] = {base(spring.n1), base(spring.n2)};
      scatter<12>(pm.k, e.stiffness, dofs);
      scatter<12>(pm.c, e.damping, dofs);
    }
  }
  // Pre-loads at rest: K_total = K + K_G (geometric_stiffness.h).
  for (const Tie& tie : model.ties) {
    const DofIndex dofs[2] = {base(tie.n1), base(tie.n2)};
    scatter<12>(pm.k, tieGeometricStiffness(pos(tie.n1), pos(tie.n2), tie.force), dofs);
  }
  for (const BodyPreload& body : model.body_preloads) {
    const Matrix3 k = bodyPreloadStiffness(pos(body.node), body.points, body.forces);
    const DofIndex rotation = base(body.node) + 3;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (k(i, j) != 0.0)
          pm.k.emplace_back(rotation + i, rotation + j, k(i, j));
  }
  for (const Mass& mass : model.masses) {
    const DofIndex dofs[1] = {base(mass.node)};
    scatter<6>(pm.m, rigidBodyMass(mass), dofs);
  }
  return pm;
}

SparseMatrix fromTriplets(DofIndex rows, DofIndex cols, const std::vector<Triplet>& t) {
  SparseMatrix s(rows, cols);
  s.setFromTriplets(t.begin(), t.end());
  s.makeCompressed();
  return s;
}

// T^T A T, symmetrised to remove round-off asymmetry of the triple product.
SparseMatrix project(const SparseMatrix& t, const SparseMatrix& a) {
  SparseMatrix r = (t.transpose() * a * t).pruned();
  SparseMatrix rt = r.transpose();
  SparseMatrix sym = 0.5 * (r + rt);
  sym.makeCompressed();
  return sym;
}

}  // namespace

System assemble(const Model& model, const AssemblyOptions& options) {
  validate(model);
  const auto index = model.nodeIndex();
  const PhysicalMatrices pm = elementMatrices(model, index);
  const DofIndex n_phys = static_cast<DofIndex>(model.nodes.size()) * kDofsPerNode;
  const auto n_inputs = static_cast<DofIndex>(pm.ground_inputs.size());

  const SparseMatrix k_phys = fromTriplets(n_phys, n_phys, pm.k);
  const SparseMatrix m_phys = fromTriplets(n_phys, n_phys, pm.m);
  const SparseMatrix c_phys = fromTriplets(n_phys, n_phys, pm.c);
  const SparseMatrix ku_phys = fromTriplets(n_phys, n_inputs, pm.ku);
  const SparseMatrix cu_phys = fromTriplets(n_phys, n_inputs, pm.cu);

  System sys;
  sys.prestressed = !model.ties.empty() || !model.body_preloads.empty() ||
                    std::any_of(model.beams.begin(), model.beams.end(),
                                [](const Beam& b) { return b.axial_force != 0.0; });
  sys.dofs = DofMap::build(model);
  if (options.drop_null_dofs) {
    // An independent DOF whose column is empty in both T^T K T and T^T M T is decoupled from
    // everything: drop it and rebuild the map without it.
    const SparseMatrix& t = sys.dofs.transformation();
    const SparseMatrix k = t.transpose() * k_phys * t;
    const SparseMatrix m = t.transpose() * m_phys * t;
    std::vector<bool> inactive(n_phys, false);
    bool any = false;
    for (DofIndex j = 0; j < k.cols(); ++j) {
      double sum = 0.0;
      for (SparseMatrix::InnerIterator it(k, j); it; ++it)
        sum += std::abs(it.value());
      for (SparseMatrix::InnerIterator it(m, j); it; ++it)
        sum += std::abs(it.value());
      if (sum == 0.0) {
        const DofRef d = sys.dofs.dofOf(j);
        inactive[sys.dofs.physical(d.node, d.direction)] = true;
        any = true;
      }
    }
    if (any)
      sys.dofs = DofMap::build(model, inactive);
  }

  const SparseMatrix& t = sys.dofs.transformation();
  sys.stiffness = project(t, k_phys);
  sys.mass = project(t, m_phys);
  sys.damping = project(t, c_phys);
  sys.input_stiffness = (t.transpose() * ku_phys).pruned();
  sys.input_damping = (t.transpose() * cu_phys).pruned();
  sys.ground_inputs = pm.ground_inputs;

  // Consistent gravity load f = T^T M_phys a, a = gravity on every translational DOF.
  Vector accel = Vector::Zero(n_phys);
  for (DofIndex n = 0; n < static_cast<DofIndex>(model.nodes.size()); ++n)
    accel.segment<3>(n * kDofsPerNode) = model.gravity;
  sys.gravity_load = t.transpose() * (m_phys * accel);
  // Travel inertia per unit forward acceleration a of the path frame (d'Alembert): the same
  // consistent projection with a = -e_x, f_a = -T^T M_phys e_x.
  Vector forward = Vector::Zero(n_phys);
  for (DofIndex n = 0; n < static_cast<DofIndex>(model.nodes.size()); ++n)
    forward(n * kDofsPerNode) = -1.0;
  sys.travel_load = t.transpose() * (m_phys * forward);

  for (const auto& [name, refs] : model.dof_sets) {
    auto& out = sys.dof_sets[name];
    for (const DofRef& ref : refs) {
      const DofIndex a = sys.dofs.active(ref.node, ref.direction);
      if (a >= 0)
        out.push_back(a);
      else
        sys.dropped_set_entries.push_back(name + ": node " + std::to_string(ref.node) + " " +
                                          directionName(ref.direction));
    }
  }
  return sys;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
