// The 2 m steel cantilever shared by the reduction tests: nodes 0..elements along x at
// x = 2 i / elements, Euler-Bernoulli beams (Iy != Iz, so the y and z bending modes differ),
// clamped at node 0. Tests add their own supports, masses and sets.
#pragma once

#include "tracked_vehicle_dynamics/fem/model.h"

namespace tracked_vehicle_dynamics {
namespace test {

inline fem::Model steelCantilever(int elements) {
  fem::Model model;
  model.name = "cantilever";
  for (int i = 0; i <= elements; ++i)
    model.addNode(i, Vector3(2.0 * i / elements, 0.0, 0.0));
  model.materials.push_back(fem::Material{"steel", 210e9, 81e9, 7850.0});
  fem::Section section;
  section.name = "bar";
  section.area = 5e-3;
  section.iy = 4e-6;
  section.iz = 1e-6;
  section.torsion = 2e-6;
  model.sections.push_back(section);
  for (int i = 0; i < elements; ++i)
    model.beams.push_back(fem::Beam{i, i + 1, "steel", "bar", Vector3::UnitZ()});
  model.fixed.push_back(fem::FixedDofs{0});
  return model;
}

}  // namespace test
}  // namespace tracked_vehicle_dynamics
